//! Joint torques by projection, the form the regressor is traced in: each link's wrench
//! written as linear in its ten inertial parameters, and each joint's unit motion carried out
//! to every link it moves.
//!
//! About the origin of a frame F fixed to link l, in F's axes, the wrench that moves the link
//! is linear in its mass m, first moment h and inertia I (about F's origin):
//! `f = m v̇ + U h`, `n = I ω̇ + ω × I ω + h × v̇`, with `U = [ω̇]× + [ω]×[ω]×` and `v̇` the
//! acceleration of F's origin (gravity included). Joint i's torque is that wrench's power in
//! joint i's unit motion `(a, b)` (angular, linear, in F's axes at F's origin), summed over the
//! links from i on:
//! `τ_i = Σ_{l≥i} m (b · v̇) + h · (Uᵀ b + v̇ × a) + Σ_k I_k (a · n_k)`, `n_k` the moment of the
//! unit inertia entry k, over the links l that joint i moves (i and its descendants: a unit
//! motion is carried from each joint to its children, and the rates likewise from each link's
//! antecedent). Each term is one parameter times its coefficient, so with symbolic
//! parameters the regressor's columns are read off one by one.
//!
//! Newton-Euler ([`super::rnea`]) carries each link's wrench back towards the base; with ten
//! symbolic parameters per link that is ten wrenches per link crossing every joint below it.
//! Here one motion (six numbers) crosses each joint per joint behind it, shared by the ten
//! coefficients (`docs/performance.md` has the counts).

use super::{Body, Chain, JointKind, Mat3, Scalar, V3};

/// A frame fixed to link l, given in joint frame J_l: its axes (columns) and its origin.
#[derive(Clone, Copy, Debug)]
pub struct LinkFrame<S> {
    /// The frame's axes in J_l's.
    pub rotation: Mat3<S>,
    /// The frame's origin in J_l.
    pub origin: V3<S>,
}

impl<S: Scalar> LinkFrame<S> {
    /// A body given in this frame (about its origin, in its axes), about J_l's origin in J_l's
    /// axes.
    pub fn carry(&self, body: &Body<S>) -> Body<S> {
        let turned = Body {
            mass: body.mass,
            h: self.rotation.mul_vec(body.h),
            inertia: Mat3::symmetric(body.inertia).congruence(&self.rotation),
        };
        turned.moved_by(self.origin)
    }
}

/// Where the bodies of [`projected_torques`] are given, when not in the joint frames.
#[derive(Clone, Copy, Debug)]
pub struct LinkFrames<'a, S> {
    /// `Some(tip)`: link l's frame is first its standard D-H frame, `J_l Transx(a) Rotx(α)` with
    /// the twist of the chain's joint l + 1 (`tip`, the last link's own, for the last link),
    /// and the rates and motions are carried through these frames, where joint l + 1 follows
    /// by `Rotz(θ) Transz(d)` alone. `None`: J_l.
    pub tip_twist: Option<Twist<S>>,
    /// Each link's frame in that frame.
    pub poses: &'a [LinkFrame<S>],
}

/// `Transx(a) Rotx(α)`: a standard D-H frame in its link's joint frame.
#[derive(Clone, Copy, Debug)]
pub struct Twist<S> {
    /// a, along J's x axis.
    pub a: S,
    /// sin α.
    pub sin_alpha: S,
    /// cos α.
    pub cos_alpha: S,
}

impl<S: Scalar> Twist<S> {
    /// `Rotx(α)ᵀ v`.
    fn untwist(&self, v: V3<S>) -> V3<S> {
        let (sa, ca) = (self.sin_alpha, self.cos_alpha);
        V3::new(v.x, ca * v.y + sa * v.z, ca * v.z - sa * v.y)
    }

    /// A unit motion at J's origin in J's axes, at the D-H frame's origin in its axes. The
    /// origin moves along x, which the twist keeps: the arm is crossed after it.
    fn motion(&self, (a, b): (V3<S>, V3<S>)) -> (V3<S>, V3<S>) {
        let a = self.untwist(a);
        (a, self.untwist(b) + a.cross(self.arm()))
    }

    /// A link's rates in J at the D-H frame: `U` is a tensor, so the shift of `v̇` by `U (a, 0, 0)`
    /// is taken after the turn, where the arm reads the same.
    fn rates(&self, w: V3<S>, wd: V3<S>, vd: V3<S>) -> Rates<S> {
        let turned = Rates::new(self.untwist(w), self.untwist(wd), self.untwist(vd));
        let vd = turned.vd + mul(&turned.u, self.arm());
        Rates { vd, ..turned }
    }

    fn arm(&self) -> V3<S> {
        let zero = self.a.zero();
        V3::new(self.a, zero, zero)
    }
}

/// Joint torques of `chain` (its bodies in J frames, or each in its own of `frames`) moving
/// with velocities `qd` and accelerations `qdd` under `gravity`: [`super::rnea`]'s, in the form
/// of the module's sum. Actuator inertia and springs are not included.
pub fn projected_torques<S: Scalar>(
    chain: &Chain<S>,
    frames: Option<&LinkFrames<'_, S>>,
    qd: &[S],
    qdd: &[S],
    gravity: V3<S>,
) -> Vec<S> {
    let twists = frames.and_then(|f| f.tip_twist).map(|tip| {
        let next = chain.joints.iter().skip(1).map(|j| Twist {
            a: j.a,
            sin_alpha: j.sin_alpha,
            cos_alpha: j.cos_alpha,
        });
        next.chain([tip]).collect::<Vec<_>>()
    });
    let twists = twists.as_deref();
    let mut links = link_rates(chain, twists, qd, qdd, gravity);
    let mut motions = joint_motions(chain, twists);
    if let Some(frames) = frames {
        let frames = frames.poses;
        for (rates, frame) in links.iter_mut().zip(frames) {
            *rates = rates.in_frame(frame);
        }
        for along in &mut motions {
            let skipped = frames.len() - along.len();
            for ((a, b), frame) in along.iter_mut().zip(&frames[skipped..]) {
                let r = &frame.rotation;
                (*a, *b) = (r.tr_mul_vec(*a), r.tr_mul_vec(*b + a.cross(frame.origin)));
            }
        }
    }
    let zero = gravity.x.zero();
    motions
        .iter()
        .enumerate()
        .map(|(i, along)| {
            let terms = along.iter().zip(&links[i..]).zip(&chain.joints[i..]);
            terms.fold(zero, |sum, ((&(a, b), rates), joint)| {
                let body = &joint.body;
                let first_moment = tr_mul(&rates.u, b) + rates.vd.cross(a);
                let inertia = body.inertia.iter().zip(&rates.moments);
                let t = inertia.fold(
                    body.mass * b.dot(rates.vd) + body.h.dot(first_moment),
                    |t, (&i, &n)| t + i * a.dot(n),
                );
                sum + t
            })
        })
        .collect()
}

/// A link's rates as the projection reads them: `ω`, `ω̇`, `v̇`, `U = [ω̇]× + [ω]×[ω]×` and
/// `I ω̇ + ω × I ω` for each unit inertia entry (`[xx, yy, zz, xy, xz, yz]`).
struct Rates<S> {
    w: V3<S>,
    wd: V3<S>,
    vd: V3<S>,
    u: [[S; 3]; 3],
    moments: [V3<S>; 6],
}

impl<S: Scalar> Rates<S> {
    fn new(w: V3<S>, wd: V3<S>, vd: V3<S>) -> Rates<S> {
        let (xx, yy, zz) = (w.x * w.x, w.y * w.y, w.z * w.z);
        let (xy, xz, yz) = (w.x * w.y, w.x * w.z, w.y * w.z);
        let u = [
            [-(yy + zz), xy - wd.z, xz + wd.y],
            [xy + wd.z, -(xx + zz), yz - wd.x],
            [xz - wd.y, yz + wd.x, -(xx + yy)],
        ];
        // `I ω̇ + ω × I ω` for I = e_x e_xᵀ is `(ω̇_x, ω_x ω_z, −ω_x ω_y)`, for
        // I = e_x e_yᵀ + e_y e_xᵀ `(ω̇_y − ω_x ω_z, ω̇_x + ω_y ω_z, ω_x² − ω_y²)`, and so on.
        // The off-diagonal sums are `U`'s entries, negated where the difference runs the
        // other way (`ω̇_y − ω_x ω_z = −U_zx`): the same node, the sign taken by the product.
        let moments = [
            V3::new(wd.x, xz, -xy),
            V3::new(-yz, wd.y, xy),
            V3::new(yz, -xz, wd.z),
            V3::new(-u[2][0], u[2][1], xx - yy),
            V3::new(u[1][0], zz - xx, -u[1][2]),
            V3::new(yy - zz, -u[0][1], u[0][2]),
        ];
        Rates {
            w,
            wd,
            vd,
            u,
            moments,
        }
    }

    /// The same link's rates in the axes of `frame` and at its origin.
    fn in_frame(&self, frame: &LinkFrame<S>) -> Rates<S> {
        let r = &frame.rotation;
        let vd = r.tr_mul_vec(self.vd + mul(&self.u, frame.origin));
        Rates::new(r.tr_mul_vec(self.w), r.tr_mul_vec(self.wd), vd)
    }
}

/// `U x`.
fn mul<S: Scalar>(u: &[[S; 3]; 3], x: V3<S>) -> V3<S> {
    Mat3 { m: *u }.mul_vec(x)
}

/// `Uᵀ x`.
fn tr_mul<S: Scalar>(u: &[[S; 3]; 3], x: V3<S>) -> V3<S> {
    Mat3 { m: *u }.tr_mul_vec(x)
}

/// Each link's rates in its joint frame, or in its D-H frame where `twists` are given:
/// Newton-Euler's forward pass.
fn link_rates<S: Scalar>(
    chain: &Chain<S>,
    twists: Option<&[Twist<S>]>,
    qd: &[S],
    qdd: &[S],
    gravity: V3<S>,
) -> Vec<Rates<S>> {
    let zero = gravity.x.zero();
    let lifted = -gravity;
    let mut links: Vec<Rates<S>> = Vec::with_capacity(chain.joints.len());
    for (i, j) in chain.joints.iter().enumerate() {
        let (w, mut wd, mut vd) = j
            .parent
            .map_or((V3::zero(zero), V3::zero(zero), lifted), |p| {
                (links[p].w, links[p].wd, links[p].vd)
            });
        let mut w = w;
        // From the parent's frame: J_{i−1}, or its D-H frame, whence J_i is `Rotz(θ) Transz(d)`.
        let (offset, into): (_, &dyn Fn(V3<S>) -> V3<S>) = match twists {
            Some(_) => (V3::new(zero, zero, j.d), &|v| j.unturn(v)),
            None => (j.offset(), &|v| j.to_child(v)),
        };
        if let Some(p) = j.parent {
            vd = vd + mul(&links[p].u, offset);
        }
        vd = into(vd);
        let (w_in, wd_in) = (into(w), into(wd));
        match j.kind {
            JointKind::Revolute => {
                w = V3::new(w_in.x, w_in.y, w_in.z + qd[i]);
                let c = w_in.cross_z(qd[i]);
                wd = V3::new(wd_in.x + c.x, wd_in.y + c.y, wd_in.z + qdd[i]);
            }
            JointKind::Prismatic => {
                (w, wd) = (w_in, wd_in);
                let c = w.cross_z(qd[i] + qd[i]);
                vd = V3::new(vd.x + c.x, vd.y + c.y, vd.z + qdd[i]);
            }
        }
        let rates = match twists {
            Some(t) => t[i].rates(w, wd, vd),
            None => Rates::new(w, wd, vd),
        };
        links.push(rates);
    }
    links
}

/// `motions[i][l − i]`: joint i's unit motion (angular, linear) in J_l's axes at J_l's origin,
/// or in link l's D-H frame where `twists` are given, for each link l ≥ i: carried from l's
/// antecedent's, and zero where l is not i's descendant.
fn joint_motions<S: Scalar>(
    chain: &Chain<S>,
    twists: Option<&[Twist<S>]>,
) -> Vec<Vec<(V3<S>, V3<S>)>> {
    let out = |l: usize, motion| twists.map_or(motion, |t: &[Twist<S>]| t[l].motion(motion));
    (0..chain.joints.len())
        .map(|i| {
            let zero = chain.joints[i].a.zero();
            let z = V3::new(zero, zero, zero.one());
            let own = match chain.joints[i].kind {
                JointKind::Revolute => (z, V3::zero(zero)),
                JointKind::Prismatic => (V3::zero(zero), z),
            };
            let mut along = vec![out(i, own)];
            for (l, j) in chain.joints.iter().enumerate().skip(i + 1) {
                // Joint i moves only its descendants.
                let Some(p) = j.parent.filter(|_| chain.supports(i, l)) else {
                    along.push((V3::zero(zero), V3::zero(zero)));
                    continue;
                };
                let (a, b) = along[p - i];
                let into = match twists {
                    Some(_) => (j.unturn(a), j.unturn(b + a.cross_z(j.d))),
                    None => (j.to_child(a), j.to_child(b + a.cross(j.offset()))),
                };
                along.push(out(l, into));
            }
            along
        })
        .collect()
}
