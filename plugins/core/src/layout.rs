named_enum!(
    /// How the viewer lays out the two views.
    Layout {
        /// One window: reference left, Close2GL right, the panel at the side.
        Split = "split",
        /// Two OS windows, "Reference (wgpu)" (with the panel) and "Close2GL".
        Windows = "windows"
    }
);
