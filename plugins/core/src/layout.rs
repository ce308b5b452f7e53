named_enum!(
    /// How the viewer lays out the two views.
    #[derive(Default)]
    Layout {
        /// One window: reference left, Close2GL right, the panel at the side.
        #[default]
        Split = "split",
        /// Two OS windows, "Reference (wgpu)" (with the panel) and "Close2GL".
        Windows = "windows"
    }
);
