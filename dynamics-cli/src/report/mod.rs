//! What `identify`, `excite` and `size` print, draw and write: their tables, their JSON, the
//! figures of an identification and of a sizing, the description file rewritten with an
//! identified robot's parameters.

pub mod description;
pub mod excite;
pub mod identify;
pub mod identify_figure;
pub mod sizing;
mod toml_joints;
