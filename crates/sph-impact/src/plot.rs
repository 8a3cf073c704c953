//! Plots (in progress).
use crate::verify::Outcome;
/// Writes a PNG plot of the profile against the exact curves.
pub fn profile_plot(_o: &Outcome, _path: &std::path::Path) -> std::io::Result<()> {
    Ok(())
}
