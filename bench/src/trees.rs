//! The robots that branch of `bench/run`'s tree rows, derived from their URDFs without the
//! joints' `<dynamics>` (which Pinocchio's algorithms and the data leave out:
//! `bench/robots/frictionless.py`), with the derivatives: a dual arm, [`BaxterFreeFingers`]
//! (`tests/data/trees/baxter_no_mimic.json`), and a hand, [`AllegroHand`]
//! (`tests/data/trees/allegro_right_hand.json`).

use dynamics_runtime::Dynamics;

/// Baxter, every joint below `base`: the head, two arms of seven joints, two free fingers on
/// each gripper (the grippers' mimic joints taken as coordinates). 19 joints.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    urdf = "robots/baxter_frictionless.urdf",
    base = "base",
    derivatives = true
)]
pub struct BaxterFreeFingers;

/// The Allegro right hand: four fingers of four joints off the palm. Its published inertias
/// break the triangle inequality (Pinocchio takes them as given). 16 joints.
#[derive(Clone, Copy, Debug, Default, Dynamics)]
#[dynamics(
    urdf = "robots/allegro_frictionless.urdf",
    base = "palm_link",
    check_inertia = false,
    derivatives = true
)]
pub struct AllegroHand;
