//! The numerics of measured and planned motion: a robot's parameters identified from measured
//! motions and torques, the exciting motions to measure them with, trajectories, and actuator
//! sizing along a motion. The library under `dynamics identify`, `dynamics excite` and
//! `dynamics size`, for a Rust program that calls them without the command line.
//!
//! Inverse dynamics is linear in the parameters, `τ = Y(q, q̇, q̈) π`. For a robot of
//! `dynamics_codegen` (`dynamics_codegen::load`), a [`Regressor`] is its base regressor `Y_B`,
//! with the joint terms asked for (actuator inertias, friction), ready to evaluate; then
//!
//! * [`identify()`]: the base parameters estimated from the samples of a CSV file
//!   ([`Samples`]): two-step weighted least squares with standard deviations, and, if asked,
//!   physically consistent standard parameters beside them;
//! * [`predict`]: the torques an estimate predicts for other samples (validation);
//! * [`excite()`]: a periodic motion within the joints' limits that keeps the condition number
//!   of the stacked `Y_B` low, to measure;
//! * [`sizing`]: along a trajectory, per joint, the peak and RMS of τ, the peak power and the
//!   five terms of τ at its peak ([`sizing::Sizer`], the terms by [`sizing::terms`]).
//!
//! ```no_run
//! use dynamics_codegen::JointColumns;
//! use dynamics_identification::{identify, Options, Regressor, Samples};
//!
//! let source = dynamics_codegen::Source { path: "robots/puma560.toml", ..Default::default() };
//! let robot = dynamics_codegen::load(&source).expect("a robot").robot;
//! let joints = vec![JointColumns::default(); robot.joints.len()];
//! let regressor = Regressor::new(&robot, joints, Vec::new())?;
//! let samples = Samples::open("measured.csv", regressor.columns(), None)?;
//! let identified = identify(&regressor, &samples, &Options::default())?;
//! for (name, value) in regressor.names().iter().zip(&identified.estimate.values) {
//!     println!("{name} = {value}");
//! }
//! # Ok::<(), dynamics_identification::Error>(())
//! ```
//!
//! The steps are public modules for what the commands print: [`identify`](mod@identify) (the
//! streamed factors, the rank, the estimate, the consistent estimate), [`excite`](mod@excite)
//! (the Fourier series, the limits, the search), [`trajectory`] (samples read from CSV, missing
//! derivatives by differences, a quintic move), the evaluation of a joint's tape four samples at a time
//! ([`joint_tape`], [`lanes`]), and the dense linear algebra by nalgebra ([`linear_algebra`]).

mod error;
mod excitation;
pub mod excite;
mod identification;
pub mod identify;
pub mod joint_tape;
pub mod lanes;
pub mod linear_algebra;
mod regressor;
pub mod sizing;
pub mod text;
pub mod trajectory;

pub use error::Error;
pub use excitation::{excite, Excited, Motion};
pub use identification::{identify, predict, Identified, Options};
pub use identify::source::{Filter, Source as Samples};
pub use regressor::Regressor;
