//! The book's statics (Niku, ch. 6.7) solved with `dynamics_runtime::statics`: Examples 6.9 and
//! 6.10 against their printed results, Problems 6.7 and 6.8 against the wrench that does the
//! same virtual work, found with the full 6×6 differential transform (eqs. 6.69-6.72) and a
//! linear solve, not with eq. 6.73.

use dynamics_runtime::statics::{joint_torques, wrench_in_frame};

/// `ᴮJ` of Paul's differential transform (eq. 6.70), `ᴮD = ᴮJ D` for a frame `b` with
/// rotation `R` and position `p`: `ᴮδ = Rᵀ δ`, `ᴮd = Rᵀ (δ × p + d)`, so
/// `ᴮJ = [[Rᵀ, −Rᵀ [p]×], [0, Rᵀ]]`.
fn differential_transform(b: &[[f64; 4]; 4]) -> [[f64; 6]; 6] {
    let r_t = |i: usize, j: usize| b[j][i];
    let p = [b[0][3], b[1][3], b[2][3]];
    let cross_p = [[0.0, -p[2], p[1]], [p[2], 0.0, -p[0]], [-p[1], p[0], 0.0]];
    let mut j = [[0.0; 6]; 6];
    for row in 0..3 {
        for col in 0..3 {
            j[row][col] = r_t(row, col);
            j[row + 3][col + 3] = r_t(row, col);
            j[row][col + 3] = -(0..3).map(|k| r_t(row, k) * cross_p[k][col]).sum::<f64>();
        }
    }
    j
}

/// `x` with `a x = y`, by Gaussian elimination with partial pivoting.
fn solve(mut a: [[f64; 6]; 6], mut y: [f64; 6]) -> [f64; 6] {
    for col in 0..6 {
        let pivot = (col..6)
            .max_by(|&i, &k| a[i][col].abs().total_cmp(&a[k][col].abs()))
            .unwrap();
        a.swap(col, pivot);
        y.swap(col, pivot);
        for row in col + 1..6 {
            let factor = a[row][col] / a[col][col];
            let pivot_row = a[col];
            for (x, p) in a[row].iter_mut().zip(pivot_row).skip(col) {
                *x -= factor * p;
            }
            y[row] -= factor * y[col];
        }
    }
    let mut x = [0.0; 6];
    for row in (0..6).rev() {
        let rest: f64 = (row + 1..6).map(|k| a[row][k] * x[k]).sum();
        x[row] = (y[row] - rest) / a[row][row];
    }
    x
}

/// The wrench in frame `b` that does the same virtual work as `wrench` for every
/// displacement: `Fᵀ D = ᴮFᵀ ᴮJ D`, so `ᴮJᵀ ᴮF = F` (eq. 6.71).
fn equivalent_by_virtual_work(b: &[[f64; 4]; 4], wrench: &[f64; 6]) -> [f64; 6] {
    let j = differential_transform(b);
    let j_t: [[f64; 6]; 6] = core::array::from_fn(|r| core::array::from_fn(|c| j[c][r]));
    solve(j_t, *wrench)
}

fn assert_close(actual: &[f64], expected: &[f64]) {
    for (a, e) in actual.iter().zip(expected) {
        assert!((a - e).abs() < 1e-12, "{actual:?} vs {expected:?}");
    }
}

/// cos 45°, which the book prints as 0.707.
const H: f64 = std::f64::consts::FRAC_1_SQRT_2;

#[test]
fn example_6_9_torques_from_the_printed_jacobian() {
    // ᴴJ of a spherical-RPY robot at one configuration, rows dx, dy, dz, δx, δy, δz.
    let jacobian = [
        [20.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [-5.0, 0.0, 1.0, 0.0, 0.0, 0.0],
        [0.0, 20.0, 0.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0, 1.0, 0.0],
        [0.0, 0.0, 0.0, 1.0, 0.0, 0.0],
        [-1.0, 0.0, 0.0, 0.0, 0.0, 1.0],
    ];
    // 1 lb along the hand's z axis and 20 lb·in about it.
    let wrench = [0.0, 0.0, 1.0, 0.0, 0.0, 20.0];
    let torques = joint_torques(&jacobian, &wrench);
    assert_eq!(torques, [-20.0, 20.0, 0.0, 0.0, 0.0, 20.0]);
    // Virtual work: moving joint j alone by 1 moves the hand by column j of ᴴJ.
    for (j, &t) in torques.iter().enumerate() {
        let work: f64 = (0..6).map(|i| wrench[i] * jacobian[i][j]).sum();
        assert_eq!(t, work);
    }
    let in_f32 = joint_torques(
        &jacobian.map(|r| r.map(|x| x as f32)),
        &wrench.map(|x| x as f32),
    );
    assert_eq!(in_f32, [-20.0, 20.0, 0.0, 0.0, 0.0, 20.0]);
}

#[test]
fn example_6_10_wrench_in_frame_b() {
    let b = [
        [0.0, 1.0, 0.0, 3.0],
        [0.0, 0.0, 1.0, 5.0],
        [1.0, 0.0, 0.0, 8.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    let wrench = [0.0, 10.0, 0.0, 0.0, 0.0, 20.0];
    let printed = [0.0, 0.0, 10.0, -10.0, 80.0, 0.0];
    assert_eq!(wrench_in_frame(&b, &wrench), printed);
    assert_close(&equivalent_by_virtual_work(&b, &wrench), &printed);
}

#[test]
fn problem_6_7_wrench_relative_to_the_object_frame() {
    let b = [
        [H, H, 0.0, 2.0],
        [0.0, 0.0, 1.0, 5.0],
        [H, -H, 0.0, 3.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    let wrench = [10.0, 0.0, 5.0, 12.0, 20.0, 0.0];
    let expected = equivalent_by_virtual_work(&b, &wrench);
    assert_close(&wrench_in_frame(&b, &wrench), &expected);
    // By hand: f × p + m = [−25 + 12, −20 + 20, 50] = [−13, 0, 50], n = (H, 0, H),
    // o = (H, 0, −H), a = (0, 1, 0).
    assert_close(
        &expected,
        &[15.0 * H, 5.0 * H, 0.0, 37.0 * H, -63.0 * H, 0.0],
    );
}

#[test]
fn problem_6_8_assembly_wrench_in_the_hand_frame() {
    // The part (and the hand aligned with it) relative to the robot's base, ᴿT_O; the push
    // (10 lb along x, 5 lb along y) and the 5 lb·in twist about x are given in the base frame.
    let b = [
        [0.0, -H, H, 4.0],
        [1.0, 0.0, 0.0, 6.0],
        [0.0, H, H, 3.0],
        [0.0, 0.0, 0.0, 1.0],
    ];
    let wrench = [10.0, 5.0, 0.0, 5.0, 0.0, 0.0];
    let expected = equivalent_by_virtual_work(&b, &wrench);
    assert_close(&wrench_in_frame(&b, &wrench), &expected);
    // By hand: f × p + m = [15 + 5, −30, 60 − 20] = [20, −30, 40], n = (0, 1, 0),
    // o = (−H, 0, H), a = (H, 0, H).
    assert_close(
        &expected,
        &[5.0, -10.0 * H, 10.0 * H, -30.0, 20.0 * H, 60.0 * H],
    );
}

/// Eq. 6.73 and the virtual-work solve agree on a frame and wrench with nothing special.
#[test]
fn any_frame_does_the_same_virtual_work() {
    let (a, b, c) = (0.3f64, -1.2f64, 2.1f64);
    let rz = [
        [a.cos(), -a.sin(), 0.0],
        [a.sin(), a.cos(), 0.0],
        [0.0, 0.0, 1.0],
    ];
    let ry = [
        [b.cos(), 0.0, b.sin()],
        [0.0, 1.0, 0.0],
        [-b.sin(), 0.0, b.cos()],
    ];
    let rx = [
        [1.0, 0.0, 0.0],
        [0.0, c.cos(), -c.sin()],
        [0.0, c.sin(), c.cos()],
    ];
    let mul = |x: [[f64; 3]; 3], y: [[f64; 3]; 3]| -> [[f64; 3]; 3] {
        core::array::from_fn(|i| core::array::from_fn(|j| (0..3).map(|k| x[i][k] * y[k][j]).sum()))
    };
    let r = mul(mul(rz, ry), rx);
    let p = [0.4, -2.5, 1.7];
    let frame: [[f64; 4]; 4] = core::array::from_fn(|i| {
        if i == 3 {
            [0.0, 0.0, 0.0, 1.0]
        } else {
            [r[i][0], r[i][1], r[i][2], p[i]]
        }
    });
    let wrench = [1.5, -0.7, 3.2, 0.25, -4.0, 0.9];
    assert_close(
        &wrench_in_frame(&frame, &wrench),
        &equivalent_by_virtual_work(&frame, &wrench),
    );
}
