//! An exciting trajectory for identification (`dynamics excite`): per joint a finite Fourier
//! series, within the joints' limits, chosen to keep the condition number of the stacked base
//! regressor low.
//!
//! * [`fourier`]: the series, its derivatives, and its scaling into the limits;
//! * [`limits`]: each joint's limits, from the options, a URDF or the defaults;
//! * [`condition`]: the condition number of the stacked `Y_B` over samples
//!   ([`crate::linear_algebra`]);
//! * [`search`]: random restarts, then a compass search, within a budget of evaluations;
//! * [`design`]: the problem put together: the coefficients searched, the motion found.

pub mod condition;
pub mod design;
pub mod fourier;
pub mod limits;
pub mod search;
