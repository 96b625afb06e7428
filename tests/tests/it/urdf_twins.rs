//! The D-H twins of two URDF robots (`robots/ur5_urdf_dh.toml`, `robots/panda_urdf_dh.toml`,
//! made by `tests/data/urdf/twins.py`) against the reference data of the URDF robots
//! themselves (`tests/data/urdf/`, Pinocchio 4.1.0's URDF loader, by `make.py`): for every
//! sample, τ, M, C, C·q̇ + g, g and both energies match to 1e-10 (scaled). The twins declare no
//! friction, so τ is Pinocchio's. The URDF robots' own test is `urdf_robots.rs`.

use dynamics_tests::reference::{check, Friction};
use dynamics_tests::robots::{PandaTwin, Ur5Twin};

#[test]
fn ur5_twin_matches_pinocchio_on_the_urdf() {
    check(&Ur5Twin, "urdf/ur5.json", Friction::None);
}

#[test]
fn panda_twin_matches_pinocchio_on_the_urdf() {
    check(&PandaTwin, "urdf/panda.json", Friction::Added);
}
