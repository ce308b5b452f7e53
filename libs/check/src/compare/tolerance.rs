//! When a difference is within its tolerance: every stage's comparison asks it the same way.

/// Whether a difference is within its tolerance; a NaN never is (a `nan` the reader let through
/// would otherwise agree with everything).
pub fn within(difference: f64, tolerance: f64) -> bool {
    difference <= tolerance
}
