//! The tests of `dynamics_codegen::trace`, by file.

mod base_parameters;
mod floating_kinematics_tests;
mod lane_solve_tests;
mod mimic_regressor_tests;
mod mimic_tests;
mod tracer;
mod tree_tests;
