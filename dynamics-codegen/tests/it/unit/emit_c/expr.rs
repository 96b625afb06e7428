use dynamics_codegen::emit_c::Precision;

#[test]
fn literals_are_exact_and_typed() {
    let table = [
        (0.1, "0.1", "0.1f"),
        (2.0, "2.0", "2.0f"),
        (-0.5, "-0.5", "-0.5f"),
        (1e-5, "0.00001", "0.00001f"),
        // The f32 nearest the f64 nearest 0.4318, printed shortest.
        (0.4318, "0.4318", "0.4318f"),
        (1.0 / 3.0, "0.3333333333333333", "0.33333334f"),
        (f64::INFINITY, "INFINITY", "INFINITY"),
        // Finite in `double`, beyond `float`'s range: its infinity, as `f32::from_f64`.
        (
            -1e39,
            "-1000000000000000000000000000000000000000.0",
            "-INFINITY",
        ),
    ];
    for (x, double, single) in table {
        assert_eq!(Precision::Double.literal(x), double);
        assert_eq!(Precision::Single.literal(x), single);
    }
}
