"""Mimic joints for `make.py`: the reduced coordinates of a URDF tree whose `<mimic>` joints
follow another joint, as projections of the full model (every joint free), and the cross-check
against Pinocchio's own mimic model.

The mimicking joint m follows q_m = k q_j + o (URDF `multiplier` k, default 1; `offset` o,
default 0) and is not a coordinate. With G the (n_full x n_red) map and q_full = G q + o:
tau = G^T tau_full(q_full, G qd, G qdd), M = G^T M_full G, C = G^T C_full G, h = G^T h_full,
g = G^T g_full, the energies those of the full model, a tip's Jacobian J_full G, the friction
torque G^T f_full(G qd), and the forward dynamics qdd = M^-1 (tau - h) (Pinocchio 4.1's aba
refuses mimic joints). G being constant, Mdot = C + C^T and g = dP/dq carry over.
"""

import numpy as np
import pinocchio as pin

from pinocchio_data import frame_kinematics, scaled_error, symmetric


class Reduced:
    """The reduced system of a `make.Full` (the full model in the front end's order) and the
    `urdf_tree.Tree` it came from."""

    def __init__(self, full, tree):
        self.full = full
        n = len(tree.names)
        self.coordinates = [i for i in range(n) if i not in tree.mimic]
        column = {i: a for a, i in enumerate(self.coordinates)}
        self.G = np.zeros((n, len(self.coordinates)))
        self.offset = np.zeros(n)
        for i, a in column.items():
            self.G[i, a] = 1.0
        for m, (j, k, o) in tree.mimic.items():
            assert j in column, f"{tree.names[m]} follows {tree.names[j]}, itself a mimic joint"
            assert m not in tree.parents, f"{tree.names[m]}: a mimic joint with joints below it"
            self.G[m, column[j]] = k
            self.offset[m] = o

    def quantities(self, q, qd, qdd):
        G = self.G
        x = self.full.quantities(G @ q + self.offset, G @ qd, G @ qdd)
        out = {k: x[k] for k in ("kinetic_energy", "potential_energy")}
        out.update({k: G.T @ x[k] for k in ("tau", "h", "g")})
        out.update({k: G.T @ x[k] @ G for k in ("M", "C")})
        out["tips"] = {f: dict(pose=t["pose"], jacobian=t["jacobian"] @ G) for f, t in x["tips"].items()}
        return out

    def mass(self, q):
        return self.G.T @ self.full.mass(self.G @ q + self.offset) @ self.G

    def potential(self, q):
        return self.full.potential(self.G @ q + self.offset)

    def forward(self, q, qd, tau):
        x = self.quantities(q, qd, 0 * qd)
        return np.linalg.solve(x["M"], tau - x["h"])

    def friction(self, qd):
        return self.G.T @ self.full.friction(self.G @ qd)

    def friction_coefficients(self):
        """Each coordinate's viscous and Coulomb coefficients: G has one entry per row, so
        G^T f(G qd) = (sum_i G_ia^2 d_i) qd_a + (sum_i |G_ia| f_i) sign(qd_a)."""
        damping, friction = self.full.friction_coefficients()
        return (self.G ** 2).T @ damping, np.abs(self.G).T @ friction

    def structure(self, tree):
        """Names, parents, limits and ancestor relation of the coordinates. A coordinate moves
        its own joint and the joints that mimic it: two coordinates are related when any of
        their joints are."""
        column = {i: a for a, i in enumerate(self.coordinates)}
        names = [tree.names[i] for i in self.coordinates]
        parents = [None if tree.parents[i] is None else column[tree.parents[i]] for i in self.coordinates]
        limits = [tree.limits[i] for i in self.coordinates]
        moves = [np.flatnonzero(self.G[:, a]) for a in range(len(names))]
        related = [[any(tree.related[i][j] for i in moves[a] for j in moves[b]) for b in range(len(names))]
                   for a in range(len(names))]
        return names, parents, limits, related

    def record(self, tree, mimic_model, states):
        """What the file says of the reduction, and the cross-check against Pinocchio's mimic
        model (the largest scaled difference per quantity)."""
        mimics = [{"joint": tree.names[m], "follows": tree.names[j], "multiplier": k, "offset": o}
                  for m, (j, k, o) in sorted(tree.mimic.items())]
        return {
            "mimic": mimics,
            "reduction": {"full_joints": tree.names, "G": self.G.tolist(), "offset": self.offset.tolist(),
                          "rule": "q_full = G q + offset; qd_full = G qd; tau = G^T tau_full"},
            "mimic_cross_check": self.cross_check(tree, mimic_model, states),
        }

    def cross_check(self, tree, mm, states):
        names = [tree.names[i] for i in self.coordinates]
        assert mm.nq == mm.nv == len(names), f"mimic model: nq {mm.nq}, nv {mm.nv}"
        perm = np.array([mm.idx_vs[mm.getJointId(n)] for n in names])

        def pinned(v):
            out = np.empty(len(perm))
            out[perm] = v
            return out

        largest, unsupported = {}, {}
        algorithms = {  # the reduced quantity each of Pinocchio's algorithms gives
            "tau": lambda d, q, qd, qdd, tau: pin.rnea(mm, d, q, qd, qdd)[perm],
            "M": lambda d, q, qd, qdd, tau: symmetric(pin.crba(mm, d, q))[np.ix_(perm, perm)],
            "h": lambda d, q, qd, qdd, tau: pin.nonLinearEffects(mm, d, q, qd)[perm],
            "g": lambda d, q, qd, qdd, tau: pin.computeGeneralizedGravity(mm, d, q)[perm],
            "C": lambda d, q, qd, qdd, tau: pin.computeCoriolisMatrix(mm, d, q, qd)[np.ix_(perm, perm)],
            "kinetic_energy": lambda d, q, qd, qdd, tau: pin.computeKineticEnergy(mm, d, q, qd),
            "potential_energy": lambda d, q, qd, qdd, tau: pin.computePotentialEnergy(mm, d, q),
            "forward": lambda d, q, qd, qdd, tau: pin.aba(mm, d, q, qd, tau)[perm],
            "tips": lambda d, q, qd, qdd, tau: frame_kinematics(mm, self.full.frames, q),
        }
        for q, qd, qdd, tau in states:
            x = self.quantities(q, qd, qdd)
            x["forward"] = self.forward(q, qd, tau)
            for k, f in algorithms.items():
                try:
                    y = f(mm.createData(), pinned(q), pinned(qd), pinned(qdd), pinned(tau))
                except Exception as e:  # Pinocchio says which algorithms refuse mimic joints
                    unsupported[k] = str(e)
                    continue
                if k == "C":  # does Pinocchio's mimic C satisfy h = C qd + g?
                    identity = scaled_error(y @ qd + x["g"], x["h"])
                    largest["h = C qd + g with Pinocchio's C"] = max(
                        largest.get("h = C qd + g with Pinocchio's C", 0.0), identity)
                if k != "tips":
                    largest[k] = max(largest.get(k, 0.0), scaled_error(y, x[k]))
                    continue
                for f_, t in y.items():
                    for part in ("pose", "jacobian"):
                        mine = x["tips"][f_][part]
                        theirs = t[part][:, perm] if part == "jacobian" else t[part]
                        largest[f"tip {part}"] = max(largest.get(f"tip {part}", 0.0), scaled_error(theirs, mine))
        return {
            "model": "pin.buildModelFromXML(snapped URDF, mimic=True)",
            "per_quantity": {k: float(f"{v:.1e}") for k, v in largest.items()},
            "largest": float(f"{max(v for k, v in largest.items() if k != 'C' and not k.startswith('h =')):.1e}"),
            "largest_note": "over every quantity but C: Pinocchio 4.1's computeCoriolisMatrix on a mimic "
                            "model satisfies neither h = C qd + g nor Mdot = C + C^T; G^T C_full G does",
            "unsupported": unsupported,
        }
