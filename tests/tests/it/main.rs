//! The workspace's integration tests, one module per file, in one test binary: one link of the
//! generator, the runtime and the reference instead of one per file, and the robots of
//! `dynamics_tests::robots` derived once for all. `cargo test -p dynamics-tests --test it
//! regressor::` runs one file's tests. The derive's compile-fail tests live with the runtime
//! that users derive through, in `dynamics-runtime/tests/ui.rs`.

mod base_parameters;
mod batch;
mod derivatives;
mod energy_drift;
mod floating_base;
mod floating_contact_forms;
mod floating_contacts;
mod floating_derivatives;
mod floating_forward;
mod floating_front;
mod floating_joint_terms;
mod floating_kinematics;
mod floating_mimic;
mod floating_regressor;
mod floating_surface_contacts;
mod forward_dynamics;
mod friction;
mod front_door;
mod generics;
mod harness;
mod keyword_fields;
mod kinematics;
mod lanes;
mod layout;
mod lint;
mod mimic;
mod mimic_derive_regressor;
mod mimic_regressor;
mod mimic_simplified;
mod niku_arm_examples;
mod niku_lagrangian_examples;
mod non_finite;
mod properties;
mod python_stubs;
mod readable_book;
mod readable_derive;
mod reference_data;
mod regressor;
mod simplified;
mod tree_tips;
mod trees;
mod urdf_robots;
mod urdf_tips;
mod urdf_trees;
mod urdf_twins;
