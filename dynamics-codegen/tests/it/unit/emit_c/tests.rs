use dynamics_codegen::emit_c::{tangent_lanes, unit_table, Precision};

/// Serial robots' headers keep the one identity table of 16 (shared by the headers included
/// together); a robot past 16 joints has a wider one under its own name and guard.
#[test]
fn the_identity_table_widens_only_past_sixteen_joints() {
    for dof in [1, 6, 7, 16] {
        let text = tangent_lanes(dof);
        assert!(text.contains("#define DYNAMICS_UNIT_H\n"), "{dof}");
        assert!(text.contains("static const double dynamics_unit[16][16] = {"));
        assert!(text.contains("static const float dynamics_unit_f32[16][16] = {"));
        assert_eq!(unit_table(dof, Precision::Single), "dynamics_unit_f32");
    }
    let text = tangent_lanes(19);
    assert!(text.contains("#define DYNAMICS_UNIT24_H\n"));
    assert!(text.contains("static const double dynamics_unit24[24][24] = {"));
    assert!(!text.contains("dynamics_unit["));
    assert_eq!(unit_table(64, Precision::Double), "dynamics_unit64");
}
