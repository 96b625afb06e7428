// The table of the generated methods' result types: the one place that spells them.
//
// `for_each_result!(callback)` calls `callback! { rows }`, one row per result shape, which the
// method table (`methods.rs`) names by its keyword (`-> matrix`). The runtime reads it to
// declare the traits' result types (`dynamics.rs`) and their nalgebra forms (`nalgebra.rs`);
// `dynamics-codegen` reads the same file (a symlink, `include!`d) for the types it writes into
// the derive's impls and modules. `T` is the scalar and `N` the number of joints wherever a
// row is used, `B` the number of base parameters (in `DynamicsBaseParameters` only), `LINKS` the
// number of links (in `DynamicsRegressor` and `DynamicsBaseParameters` only: `N` but on a robot
// with mimic joints), `TIPS` the number of tips (in `TipKinematics` only); a type name other
// than `T`, `N`, `B`, `LINKS`, `TIPS`, `Result` and `Option` is the runtime's.
//
//     /// What the result is.
//     matrix {
//         variant: Matrix,                         // the codegen enum's variant (`Returns`)
//         array: [[T; N]; N],                      // the trait method's result type
//         nalgebra: SMatrix<T, N, N>,              // the `_na` wrapper's result type
//         to_nalgebra: |value| matrix(&value),     // the array result into it
//         rows: [[T; N]; N],                       // what the generated module's function returns
//         from_rows: |value| value,                // that, into the trait's result
//     }
//
// `for_each_result!(callback $)` passes a `$` first, for a callback that defines macros of its
// own from the rows (the runtime's `array_result!`, `nalgebra_result!`, `to_nalgebra!`, in
// `dynamics.rs`; the codegen's `returns!`).

/// Calls `$callback!` with the rows of the result table (see the comment at the top of
/// `results.rs`), after the optional `$` given.
macro_rules! for_each_result {
    ($callback:ident $($dollar:tt)?) => {
        $callback! {
            $($dollar)?
            /// `[[T; N]; N]`.
            matrix {
                variant: Matrix,
                array: [[T; N]; N],
                nalgebra: SMatrix<T, N, N>,
                to_nalgebra: |value| matrix(&value),
                rows: [[T; N]; N],
                from_rows: |value| value,
            }
            /// `[T; N]`.
            vector {
                variant: Vector,
                array: [T; N],
                nalgebra: SVector<T, N>,
                to_nalgebra: |value| SVector::from(value),
                rows: [T; N],
                from_rows: |value| value,
            }
            /// `T`.
            scalar {
                variant: Scalar,
                array: T,
                nalgebra: T,
                to_nalgebra: |value| value,
                rows: T,
                from_rows: |value| value,
            }
            /// A `Pose`: a rotation and a position; in the generated module, its rows
            /// `[R | p]`.
            pose {
                variant: Pose,
                array: Pose<T>,
                nalgebra: Isometry3<T>,
                to_nalgebra: |value| isometry(&value),
                rows: [[T; 4]; 3],
                from_rows: |value| Pose::from_rows(value),
            }
            /// A `Pose` per link.
            poses {
                variant: Poses,
                array: [Pose<T>; N],
                nalgebra: [Isometry3<T>; N],
                to_nalgebra: |value| value.map(|p| isometry(&p)),
                rows: [[[T; 4]; 3]; N],
                from_rows: |value| value.map(Pose::from_rows),
            }
            /// A Jacobian's six rows `[dx, dy, dz, δx, δy, δz]`, a column per joint.
            jacobian {
                variant: Jacobian,
                array: [[T; N]; 6],
                nalgebra: SMatrix<T, 6, N>,
                to_nalgebra: |value| SMatrix::from_fn(|i, j| value[i][j]),
                rows: [[T; N]; 6],
                from_rows: |value| value,
            }
            /// A spatial 6-vector `[T; 6]`: a linear and an angular part.
            spatial {
                variant: Spatial,
                array: [T; 6],
                nalgebra: SVector<T, 6>,
                to_nalgebra: |value| SVector::from(value),
                rows: [T; 6],
                from_rows: |value| value,
            }
            /// A matrix solved with the LDLᵀ of `M`, or `NotPositiveDefinite`; in the
            /// generated module, `None` where a pivot is not positive.
            solved_matrix {
                variant: SolvedMatrix,
                array: Result<[[T; N]; N], NotPositiveDefinite>,
                nalgebra: Result<SMatrix<T, N, N>, NotPositiveDefinite>,
                to_nalgebra: |value| value.map(|m| matrix(&m)),
                rows: Option<[[T; N]; N]>,
                from_rows: |value| value.ok_or(NotPositiveDefinite),
            }
            /// A vector solved with the LDLᵀ of `M`, or `NotPositiveDefinite`.
            solved_vector {
                variant: SolvedVector,
                array: Result<[T; N], NotPositiveDefinite>,
                nalgebra: Result<SVector<T, N>, NotPositiveDefinite>,
                to_nalgebra: |value| value.map(SVector::from),
                rows: Option<[T; N]>,
                from_rows: |value| value.ok_or(NotPositiveDefinite),
            }
            /// `∂τ/∂q` and `∂τ/∂q̇`; in the generated module, the two blocks.
            inverse_derivatives {
                variant: InverseDerivatives,
                array: InverseDynamicsDerivatives<[[T; N]; N]>,
                nalgebra: InverseDynamicsDerivatives<SMatrix<T, N, N>>,
                to_nalgebra: |value| value.map(|m| matrix(&m)),
                rows: [[[T; N]; N]; 2],
                from_rows: |value| InverseDynamicsDerivatives::from_blocks(value),
            }
            /// `q̈` and `∂q̈/∂q`, `∂q̈/∂q̇`, `∂q̈/∂τ`, or `NotPositiveDefinite`; in the
            /// generated module, `q̈` and the three blocks, `None` where a pivot is not
            /// positive.
            forward_derivatives {
                variant: ForwardDerivatives,
                array: Result<ForwardDynamicsDerivatives<[T; N], [[T; N]; N]>, NotPositiveDefinite>,
                nalgebra: Result<
                    ForwardDynamicsDerivatives<SVector<T, N>, SMatrix<T, N, N>>,
                    NotPositiveDefinite,
                >,
                to_nalgebra: |value| value.map(|d| d.map(SVector::from, |m| matrix(&m))),
                rows: Option<([T; N], [[[T; N]; N]; 3])>,
                from_rows: |value| value
                    .map(ForwardDynamicsDerivatives::from_parts)
                    .ok_or(NotPositiveDefinite),
            }
            /// Per joint `i` and link `j`, the 10 columns of `∂τ_i/∂π_j`, `π_j` in the order
            /// `[m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]`; as nalgebra, one `N × 10`
            /// block per link.
            link_columns {
                variant: LinkColumns,
                array: [[[T; 10]; LINKS]; N],
                nalgebra: [SMatrix<T, N, 10>; LINKS],
                to_nalgebra: |value| core::array::from_fn(|j| SMatrix::from_fn(|i, k| value[i][j][k])),
                rows: [[[T; 10]; LINKS]; N],
                from_rows: |value| value,
            }
            /// Per joint `i`, its 4 columns `[q̈_i, q̇_i, sign(q̇_i), 1]` (`tanh(q̇_i / ε)` for a
            /// smoothed Coulomb term), of the actuator inertia and the friction coefficients.
            joint_columns {
                variant: JointColumns,
                array: [[T; 4]; LINKS],
                nalgebra: SMatrix<T, LINKS, 4>,
                to_nalgebra: |value| SMatrix::from_fn(|i, k| value[i][k]),
                rows: [[T; 4]; LINKS],
                from_rows: |value| value,
            }
            /// Per link, its 10 standard parameters `[m, m cx, m cy, m cz, Ixx, Ixy, Iyy, Ixz,
            /// Iyz, Izz]`.
            link_parameters {
                variant: LinkParameters,
                array: [[T; 10]; LINKS],
                nalgebra: [SVector<T, 10>; LINKS],
                to_nalgebra: |value| value.map(SVector::from),
                rows: [[T; 10]; LINKS],
                from_rows: |value| value,
            }
            /// Per joint `i`, the columns of the base parameters, `B` of them.
            base_columns {
                variant: BaseColumns,
                array: [[T; B]; N],
                nalgebra: SMatrix<T, N, B>,
                to_nalgebra: |value| SMatrix::from_fn(|i, j| value[i][j]),
                rows: [[T; B]; N],
                from_rows: |value| value,
            }
            /// Per base parameter, its coefficients on the links' standard parameters.
            base_link_map {
                variant: BaseLinkMap,
                array: [[[T; 10]; LINKS]; B],
                nalgebra: [SMatrix<T, LINKS, 10>; B],
                to_nalgebra: |value| value.map(|m| SMatrix::from_fn(|i, k| m[i][k])),
                rows: [[[T; 10]; LINKS]; B],
                from_rows: |value| value,
            }
            /// Per base parameter, its coefficients on the joints' parameters.
            base_joint_map {
                variant: BaseJointMap,
                array: [[[T; 4]; LINKS]; B],
                nalgebra: [SMatrix<T, LINKS, 4>; B],
                to_nalgebra: |value| value.map(|m| SMatrix::from_fn(|i, k| m[i][k])),
                rows: [[[T; 4]; LINKS]; B],
                from_rows: |value| value,
            }
            /// A `Pose` per tip; in the generated module, their rows `[R | p]`.
            tip_poses {
                variant: TipPoses,
                array: [Pose<T>; TIPS],
                nalgebra: [Isometry3<T>; TIPS],
                to_nalgebra: |value| value.map(|p| isometry(&p)),
                rows: [[[T; 4]; 3]; TIPS],
                from_rows: |value| value.map(Pose::from_rows),
            }
            /// A Jacobian per tip, each six rows `[dx, dy, dz, δx, δy, δz]` of a column per
            /// joint.
            tip_jacobians {
                variant: TipJacobians,
                array: [[[T; N]; 6]; TIPS],
                nalgebra: [SMatrix<T, 6, N>; TIPS],
                to_nalgebra: |value| value.map(|j| SMatrix::from_fn(|i, k| j[i][k])),
                rows: [[[T; N]; 6]; TIPS],
                from_rows: |value| value,
            }
            /// A spatial 6-vector per tip, a linear and an angular part.
            tip_spatials {
                variant: TipSpatials,
                array: [[T; 6]; TIPS],
                nalgebra: [SVector<T, 6>; TIPS],
                to_nalgebra: |value| value.map(SVector::from),
                rows: [[T; 6]; TIPS],
                from_rows: |value| value,
            }
            /// The `B` base parameters.
            base_vector {
                variant: BaseVector,
                array: [T; B],
                nalgebra: SVector<T, B>,
                to_nalgebra: |value| SVector::from(value),
                rows: [T; B],
                from_rows: |value| value,
            }
        }
    };
}
