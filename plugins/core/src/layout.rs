/// A view the window shows: where the viewer places it, and what the labels and legends over
/// it say.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum View {
    Reference,
    Close2gl,
    /// The pipeline seen from outside (`close2gl_gpu::outside`).
    Outside,
}

named_enum!(
    /// How the viewer lays out the two views.
    Layout {
        /// One window: reference left, Close2GL right, the panel at the side.
        Split = "split",
        /// Two OS windows, "Reference (wgpu)" (with the panel) and "Close2GL".
        Windows = "windows"
    }
);
