//! What `identify` and `excite` print and draw: their tables, their JSON, the figure of an
//! identification.

pub mod excite;
pub mod identify;
pub mod identify_figure;
