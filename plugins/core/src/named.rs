//! Enums with snake_case names that the config, the command line and the panel share.

/// An enum whose every value has a name: the config parses it, the panel labels buttons with it.
pub trait NamedEnum: Copy + PartialEq + 'static {
    /// Every value, in the order the panel shows them.
    const ALL: &'static [Self];

    fn name(self) -> &'static str;

    fn from_name(text: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|v| v.name() == text)
    }
}

/// Defines a config-facing enum with its snake_case names in one place, as inherent items and as
/// [`NamedEnum`].
macro_rules! named_enum {
    ($(#[$meta:meta])* $name:ident { $($(#[$vmeta:meta])* $variant:ident = $text:literal),+ $(,)? }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
        pub enum $name { $($(#[$vmeta])* $variant),+ }

        impl $name {
            pub const ALL: &'static [$name] = &[$($name::$variant),+];

            pub fn name(self) -> &'static str {
                match self { $($name::$variant => $text),+ }
            }

            pub fn from_name(text: &str) -> Option<Self> {
                <Self as $crate::NamedEnum>::from_name(text)
            }
        }

        impl $crate::NamedEnum for $name {
            const ALL: &'static [$name] = $name::ALL;

            fn name(self) -> &'static str {
                $name::name(self)
            }
        }
    };
}
