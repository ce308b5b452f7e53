//! The eight `camera` lines: the pose (position, u, v, n) and the view volume (hfov, vfov,
//! near, far), in any order, each once, with the volume's ranges checked as soon as a line
//! shows them broken.

use glam::DVec3;

use super::CameraLines;
use super::syntax::{FormatError, Line, Slot, set_once};

/// Every camera line's key and what its numbers are called, in the order the writer writes
/// them and an error about a missing one names them.
pub(crate) const LINES: [(&str, &str); 8] = [
    ("camera position", "X Y Z"),
    ("camera u", "X Y Z"),
    ("camera v", "X Y Z"),
    ("camera n", "X Y Z"),
    ("camera hfov", "DEG"),
    ("camera vfov", "DEG"),
    ("camera near", "D"),
    ("camera far", "D"),
];

/// Camera line `i`'s shape: `camera u X Y Z`.
pub(crate) fn shape(i: usize) -> String {
    let (key, numbers) = LINES[i];
    format!("{key} {numbers}")
}

/// The camera lines read so far.
#[derive(Default)]
pub(crate) struct CameraSlots {
    /// position, u, v, n.
    pub(crate) pose: [Slot<DVec3>; 4],
    pub(crate) hfov: Slot<f64>,
    pub(crate) vfov: Slot<f64>,
    pub(crate) near: Slot<f64>,
    pub(crate) far: Slot<f64>,
}

impl CameraSlots {
    pub(crate) fn read(&mut self, line: &Line) -> Result<(), FormatError> {
        let which = line.fields.get(1).copied().unwrap_or_default();
        let Some(i) = LINES
            .iter()
            .position(|(key, _)| key.strip_prefix("camera ") == Some(which))
        else {
            let shape = "camera position|u|v|n X Y Z' or 'camera hfov|vfov|near|far D";
            return Err(line.wrong_shape(shape));
        };
        let ((key, name), shape) = (LINES[i], &shape(i));
        if i < 4 {
            line.expect_fields(5, shape)?;
            let xyz = line.numbers(2, shape, |k| ["X", "Y", "Z"][k].to_string())?;
            return set_once(&mut self.pose[i], DVec3::from_slice(&xyz), line, key);
        }
        line.expect_fields(3, shape)?;
        let x = line.number(2, name, shape)?;
        match which {
            "hfov" | "vfov" if !(x > 0.0 && x < 180.0) => {
                Err(line.expected(&format!("'{shape}' with DEG in (0, 180)")))
            }
            "hfov" => set_once(&mut self.hfov, x, line, key),
            "vfov" => set_once(&mut self.vfov, x, line, key),
            "near" => {
                check_volume(line, shape, x, self.far, |near, far| near < far, "< far")?;
                set_once(&mut self.near, x, line, key)
            }
            _ => {
                check_volume(line, shape, x, self.near, |far, near| far > near, "> near")?;
                set_once(&mut self.far, x, line, key)
            }
        }
    }

    /// The line that gave the pose's first given part, if any did.
    pub(crate) fn pose_line(&self) -> Option<usize> {
        self.pose.iter().flatten().map(|&(_, at)| at).min()
    }

    /// The whole camera, or the index in [`LINES`] of the first line the file lacks.
    pub(crate) fn lines(&self) -> Result<CameraLines, usize> {
        let pose = |i: usize| self.pose[i].map(|(x, _)| x).ok_or(i);
        let volume = |slot: Slot<f64>, i: usize| slot.map(|(x, _)| x).ok_or(i);
        Ok(CameraLines {
            position: pose(0)?,
            u: pose(1)?,
            v: pose(2)?,
            n: pose(3)?,
            hfov: volume(self.hfov, 4)?,
            vfov: volume(self.vfov, 5)?,
            near: volume(self.near, 6)?,
            far: volume(self.far, 7)?,
        })
    }
}

/// `near` and `far` are positive, and far beyond near once both are known: the error is at
/// whichever of the two lines comes second. `other` is the one read before, if it was.
fn check_volume(
    line: &Line,
    shape: &str,
    x: f64,
    other: Slot<f64>,
    ordered: fn(f64, f64) -> bool,
    rule: &str,
) -> Result<(), FormatError> {
    if x <= 0.0 {
        return Err(line.expected(&format!("'{shape}' with D > 0")));
    }
    match other {
        Some((y, at)) if !ordered(x, y) => {
            let what = format!("'{shape}' with D {rule} ({y:?}, line {at})");
            Err(line.expected(&what))
        }
        _ => Ok(()),
    }
}
