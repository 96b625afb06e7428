//! The frames of a floating base named by `tips = [..]`: on a fixed base the tips choose the
//! branches the robot keeps, but a floating base's dynamics need every branch, so the URDF's
//! loader is asked for the named links followed by every moving leaf
//! (`urdf::moving_leaves`), and the robot's tips are cut back to the named ones.
//! Without `tips`, a floating base's frames are its moving leaves (a quadruped's feet).

use super::attrs::Attrs;
use super::errors::Errors;
use super::named_file::read_relative;
use syn::LitStr;

/// The links to ask the loader of `urdf` for as tips, and on a floating base the number of
/// them that are its frames: `named` as they are on a fixed base; on a floating base `named`
/// then every moving leaf (every branch kept), or without `named` the moving leaves alone,
/// which are then its frames.
pub(super) fn every_branch(
    attrs: &Attrs,
    urdf: &LitStr,
    named: &[String],
) -> (Vec<String>, Option<usize>) {
    let mut tips = named.to_vec();
    let Some(floating) = &attrs.floating else {
        return (tips, None);
    };
    // The file's errors are told where it is loaded.
    let (mut ignored, mut untracked) = (Errors::default(), None);
    if let Some((_, text)) = read_relative(urdf, &mut ignored, &mut untracked) {
        let base = floating.link.as_ref().map(LitStr::value);
        tips.extend(super::urdf::moving_leaves(&text, base.as_deref()));
    }
    let frames = if named.is_empty() {
        tips.len()
    } else {
        named.len()
    };
    (tips, Some(frames))
}
