//! The words the files spell their switches with. They are [`NamedEnum`]s like the config's, so
//! that one `from_name` reads them all and the writer cannot spell them differently.

use close2gl_core::NamedEnum;

use super::{Axis, Culling, TraceClipping};

impl NamedEnum for Culling {
    const ALL: &'static [Self] = &[Self::Off, Self::Ccw, Self::Cw];

    fn name(self) -> &'static str {
        match self {
            Self::Off => "off",
            Self::Ccw => "ccw",
            Self::Cw => "cw",
        }
    }
}

impl NamedEnum for TraceClipping {
    const ALL: &'static [Self] = &[Self::Simple, Self::Full, Self::None];

    fn name(self) -> &'static str {
        match self {
            Self::Simple => "simple",
            Self::Full => "full",
            Self::None => "none",
        }
    }
}

impl NamedEnum for Axis {
    const ALL: &'static [Self] = &[Self::U, Self::V, Self::N];

    fn name(self) -> &'static str {
        match self {
            Self::U => "u",
            Self::V => "v",
            Self::N => "n",
        }
    }
}

/// The names of `T` as a line's shape spells a choice: `off|ccw|cw`.
pub(crate) fn choices<T: NamedEnum>() -> String {
    let names: Vec<&str> = T::ALL.iter().map(|v| v.name()).collect();
    names.join("|")
}
