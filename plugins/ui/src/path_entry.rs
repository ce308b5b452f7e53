//! A path typed into the panel: a one-line field and its button, as the model and texture
//! sections both ask for a file.

/// A field editing `path`, with `button` beside it (`reserve` points are kept for the button).
/// Returns the trimmed path when the button is clicked or Enter is pressed in the field, unless
/// it is empty.
pub fn path_entry<'a>(
    ui: &mut egui::Ui,
    path: &'a mut String,
    hint: &str,
    button: &str,
    reserve: f32,
) -> Option<&'a str> {
    let mut chosen = false;
    ui.horizontal(|ui| {
        let field = egui::TextEdit::singleline(path)
            .hint_text(hint)
            .desired_width(ui.available_width() - reserve);
        let entered = ui.add(field).lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        chosen = ui.button(button).clicked() || entered;
    });
    let path = path.trim();
    (chosen && !path.is_empty()).then_some(path)
}
