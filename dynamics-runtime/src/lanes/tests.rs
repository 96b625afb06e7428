//! Each lane against the scalar, bit for bit, operation by operation.

// std for the tests alone, with or without the crate's `std` feature.
extern crate std;
use std::{format, vec::Vec};

use super::{gather, F32x4, F32x8, F64x2, F64x4, F64x8, Lanes, SplitLanes};
use crate::Real;

/// Arguments that take every path: ordinary, tiny, huge, signed zeros, infinities, NaN.
const SPECIAL: [f64; 12] = [
    0.7,
    -2.5,
    1e-30,
    -0.0,
    0.0,
    1e6,
    -3e5,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
    123.456,
    -1.0,
];

/// Every unary and binary operation of `V` on lanes of `xs`, against `E` lane by lane.
fn check<V: Lanes<L>, const L: usize>(xs: &[V::Scalar], bits: impl Fn(V::Scalar) -> u64) {
    let same = |v: V, f: &dyn Fn(usize) -> V::Scalar, what: &str| {
        for (l, x) in v.to_array().into_iter().enumerate() {
            assert_eq!(bits(x), bits(f(l)), "{what}, lane {l}");
        }
    };
    for start in 0..xs.len() {
        let lane = |k: usize| core::array::from_fn(|l| xs[(start + l * 5 + k) % xs.len()]);
        let (a, b, c) = (lane(0), lane(1), lane(2));
        let (va, vb, vc) = (V::from_array(a), V::from_array(b), V::from_array(c));
        same(va + vb, &|l| a[l] + b[l], "+");
        same(va - vb, &|l| a[l] - b[l], "-");
        same(va * vb, &|l| a[l] * b[l], "*");
        same(va / vb, &|l| a[l] / b[l], "/");
        same(-va, &|l| -a[l], "neg");
        same(va.mul_add(vb, vc), &|l| a[l].mul_add(b[l], c[l]), "mul_add");
        same(va.sign(), &|l| a[l].sign(), "sign");
        same(va.tanh(), &|l| a[l].tanh(), "tanh");
        same(va.sin(), &|l| a[l].sin(), "sin");
        same(va.cos(), &|l| a[l].cos(), "cos");
        let (s4, _) = V::sin_cos_4([va, vb, vc, va]);
        same(s4[1], &|l| b[l].sin(), "sin_cos_4");
        let (_, c8) = V::sin_cos_8([va, vb, vc, va, vb, vc, va, vb]);
        same(c8[5], &|l| c[l].cos(), "sin_cos_8");
        assert_eq!(va.all_positive(), a.iter().all(Real::all_positive));
        let copy = va;
        assert_eq!(va == copy, a.iter().zip(&a).all(|(x, y)| x == y));
    }
    same(V::from_f64(0.1), &|_| V::Scalar::from_f64(0.1), "from_f64");
    same(V::ZERO + V::ONE, &|_| V::Scalar::ONE, "constants");
    same(V::default(), &|_| V::Scalar::ZERO, "default");
}

#[test]
#[allow(clippy::cast_possible_truncation)]
fn every_operation_is_the_scalars_lane_by_lane() {
    let f32s: Vec<f32> = SPECIAL.iter().map(|&x| x as f32).collect();
    check::<F64x8, 8>(&SPECIAL, f64::to_bits);
    check::<F64x4, 4>(&SPECIAL, f64::to_bits);
    check::<F64x2, 2>(&SPECIAL, f64::to_bits);
    check::<F32x8, 8>(&f32s, |x| u64::from(x.to_bits()));
    check::<F32x4, 4>(&f32s, |x| u64::from(x.to_bits()));
}

/// The portable backends as lane types of their own, to check them on every target (on
/// x86-64 the real types use registers).
mod portable {
    use super::super::{portable, Lanes, Real};
    mod p64x8 {
        use super::{portable::f64x8 as backend, Lanes, Real};
        lane_type!(P64x8, f64, 8, backend);
    }
    mod p64x4 {
        use super::{portable::f64x4 as backend, Lanes, Real};
        lane_type!(P64x4, f64, 4, backend);
    }
    mod p64x2 {
        use super::{portable::f64x2 as backend, Lanes, Real};
        lane_type!(P64x2, f64, 2, backend);
    }
    mod p32x8 {
        use super::{portable::f32x8 as backend, Lanes, Real};
        lane_type!(P32x8, f32, 8, backend);
    }
    mod p32x4 {
        use super::{portable::f32x4 as backend, Lanes, Real};
        lane_type!(P32x4, f32, 4, backend);
    }
    pub(super) use {p32x4::P32x4, p32x8::P32x8, p64x2::P64x2, p64x4::P64x4, p64x8::P64x8};
}

#[test]
#[allow(clippy::cast_possible_truncation)]
fn the_portable_backends_too() {
    use portable::{P32x4, P32x8, P64x2, P64x4, P64x8};
    let f32s: Vec<f32> = SPECIAL.iter().map(|&x| x as f32).collect();
    check::<P64x8, 8>(&SPECIAL, f64::to_bits);
    check::<P64x4, 4>(&SPECIAL, f64::to_bits);
    check::<P64x2, 2>(&SPECIAL, f64::to_bits);
    check::<P32x8, 8>(&f32s, |x| u64::from(x.to_bits()));
    check::<P32x4, 4>(&f32s, |x| u64::from(x.to_bits()));
}

#[test]
fn one_failing_lane_fails_the_pivot_test() {
    assert!(F64x4::from_array([1.0, 2.0, 1e-300, 3.0]).all_positive());
    assert!(!F64x4::from_array([1.0, 2.0, 0.0, 3.0]).all_positive());
    assert!(!F32x8::from_array([1.0, 2.0, 1.0, 3.0, 1.0, -1.0, 1.0, 1.0]).all_positive());
    assert!(!F64x2::from_array([f64::NAN, 1.0]).all_positive());
    assert!(!F64x8::from_array([1.0, 2.0, 1.0, 3.0, 1.0, 1.0, 1.0, -0.0]).all_positive());
    assert!(F64x8::from_array([1.0; 8]).all_positive());
}

#[test]
fn gather_and_split_are_inverse() {
    let states = [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]];
    let v: [F64x2; 3] = gather(&states);
    assert_eq!(v[2].to_array(), [3.0, 6.0]);
    assert_eq!(v.split_lanes(), states);
    let m = [v, v].split_lanes();
    assert_eq!(m[1], [[4.0, 5.0, 6.0]; 2]);
    assert_eq!(format!("{:?}", v[0]), "F64x2([1.0, 4.0])");
}

/// `transpose` exchanges lanes and values, whatever the backend (AVX2's shuffles for `F64x4`,
/// AVX-512's for `F64x8` in a build for this CPU), and twice is the identity.
#[test]
fn transpose_exchanges_lanes_and_values() {
    fn check<V: Lanes<L>, const L: usize>()
    where
        V::Scalar: PartialEq + core::fmt::Debug,
    {
        let values: [V; L] = core::array::from_fn(|j| {
            V::from_array(core::array::from_fn(|l| {
                <V::Scalar as Real>::from_f64((10 * j + l) as f64)
            }))
        });
        let t = V::transpose(values);
        for (j, value) in t.iter().enumerate() {
            for (l, x) in value.to_array().into_iter().enumerate() {
                assert_eq!(x, values[l].to_array()[j]);
            }
        }
        let back = V::transpose(t).map(V::to_array);
        assert_eq!(back, values.map(V::to_array));
    }
    check::<F64x8, 8>();
    check::<F64x4, 4>();
    check::<F64x2, 2>();
    check::<F32x8, 8>();
    check::<F32x4, 4>();
}

/// A group of forward derivatives written in place (whole rows, `write_lanes`) is each lane's
/// value, as `lane` gives it; an `Err`, or outputs not all `Ok`, lane by lane.
#[test]
fn forward_derivatives_written_in_place_are_each_lanes() {
    use crate::{ForwardDynamicsDerivatives, NotPositiveDefinite};
    type Single = Result<ForwardDynamicsDerivatives<[f64; 3], [[f64; 3]; 3]>, NotPositiveDefinite>;
    let value = |seed: usize| -> F64x8 {
        F64x8::from_array(core::array::from_fn(|l| (seed * 8 + l) as f64 * 0.5 - 7.0))
    };
    let matrix = |base: usize| -> [[F64x8; 3]; 3] {
        core::array::from_fn(|i| core::array::from_fn(|j| value(base + 3 * i + j)))
    };
    let group: Result<_, NotPositiveDefinite> = Ok(ForwardDynamicsDerivatives::from_parts((
        core::array::from_fn(value),
        [matrix(3), matrix(12), matrix(21)],
    )));
    let zero = ForwardDynamicsDerivatives::from_parts(([0.0; 3], [[[0.0; 3]; 3]; 3]));
    for start in [Ok(zero), Err(NotPositiveDefinite)] {
        let mut outs: [Single; 8] = [start; 8];
        outs[5] = Ok(zero);
        group.write_lanes(outs.each_mut());
        for (l, out) in outs.iter().enumerate() {
            assert_eq!(*out, group.lane(l), "lane {l}");
        }
    }
    let failed: Result<ForwardDynamicsDerivatives<[F64x8; 3], [[F64x8; 3]; 3]>, _> =
        Err(NotPositiveDefinite);
    let mut outs: [Single; 8] = [Ok(zero); 8];
    failed.write_lanes(outs.each_mut());
    assert!(outs.iter().all(Result::is_err));
}
