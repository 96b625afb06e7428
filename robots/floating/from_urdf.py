#!/usr/bin/env python3
"""Writes a description file (TOML, `docs/description-files.md`) for a robot on a floating base
from its URDF: `python3 robots/floating/from_urdf.py robots/urdf/floating/solo12.urdf
robots/floating/solo12.toml`.

The root link and every link fixed to it (by `fixed` joints, recursively) become the file's
`[floating]` body; each moving joint a `[[joints]]` entry given URDF style (`origin`, `axis`,
`parent` by name, 0 for the base), its link the joint's child link with every link fixed below
it combined into one body in the child's frame (mass, centre of mass, inertia about it). Joints
in the URDF front end's order: depth first from the root, a link's child joints in the file's
order. Numbers are written with Python's `repr` (shortest round trip of the double the
combination gives): the file's robot is the URDF's to within a few ulp. Only the standard
library is used.
"""

import math
import sys
import xml.etree.ElementTree as ET


def floats(text, default):
    return [float(x) for x in text.split()] if text is not None else list(default)


def rotation(rpy):
    """URDF's fixed-axis roll, pitch, yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    r, p, y = rpy
    cr, sr, cp, sp, cy, sy = math.cos(r), math.sin(r), math.cos(p), math.sin(p), math.cos(y), math.sin(y)
    return [[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
            [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
            [-sp, cp * sr, cp * cr]]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def origin(element):
    """The (R, p) of an `<origin>` child, identity without one."""
    o = element.find("origin") if element is not None else None
    if o is None:
        return rotation([0, 0, 0]), [0.0, 0.0, 0.0]
    return rotation(floats(o.get("rpy"), [0, 0, 0])), floats(o.get("xyz"), [0, 0, 0])


def body(link):
    """A link's (mass, com, inertia about the com) in its own frame."""
    inertial = link.find("inertial")
    if inertial is None:
        return 0.0, [0.0] * 3, [[0.0] * 3 for _ in range(3)]
    mass = float(inertial.find("mass").get("value"))
    r, p = origin(inertial)
    i = inertial.find("inertia")
    g = {k: float(i.get(k, "0")) for k in ("ixx", "iyy", "izz", "ixy", "ixz", "iyz")}
    tensor = [[g["ixx"], g["ixy"], g["ixz"]], [g["ixy"], g["iyy"], g["iyz"]], [g["ixz"], g["iyz"], g["izz"]]]
    return mass, p, matmul(matmul(r, tensor), transpose(r))


def placed(b, r, p):
    """Body `b` carried by the placement (R, p) into the parent's frame."""
    mass, com, tensor = b
    moved = [sum(r[i][k] * com[k] for k in range(3)) + p[i] for i in range(3)]
    return mass, moved, matmul(matmul(r, tensor), transpose(r))


def combine(parts):
    if len(parts) == 1:
        return parts[0]
    mass = sum(m for m, _, _ in parts)
    if mass == 0:
        return 0.0, [0.0] * 3, [[0.0] * 3 for _ in range(3)]
    com = [sum(m * c[i] for m, c, _ in parts) / mass for i in range(3)]
    tensor = [[0.0] * 3 for _ in range(3)]
    for m, c, t in parts:
        d = [c[i] - com[i] for i in range(3)]
        dd = sum(x * x for x in d)
        for i in range(3):
            for j in range(3):
                tensor[i][j] += t[i][j] + m * ((dd if i == j else 0.0) - d[i] * d[j])
    return mass, com, tensor


def number(x):
    return repr(0.0 if x == 0 else x)


def numbers(xs):
    return "[" + ", ".join(number(x) for x in xs) + "]"


def body_lines(b):
    mass, com, t = b
    inertia = [t[0][0], t[1][1], t[2][2], t[0][1], t[0][2], t[1][2]]
    return [f"mass = {number(mass)}", f"com = {numbers(com)}", f"inertia = {numbers(inertia)}"]


def main(urdf, out):
    robot = ET.parse(urdf).getroot()
    links = {l.get("name"): l for l in robot.findall("link")}
    joints = robot.findall("joint")
    children = {}
    for j in joints:
        children.setdefault(j.find("parent").get("link"), []).append(j)
    root = next(iter(set(links) - {j.find("child").get("link") for j in joints}))

    def rigid(link):
        """`link` and the links fixed below it, in its frame; the moving joints below them,
        each with the placement of its parent link in `link`'s frame."""
        parts, moving = [body(links[link])], []
        for j in children.get(link, []):
            r, p = origin(j)
            if j.get("type") == "fixed":
                sub, below = rigid(j.find("child").get("link"))
                parts.append(placed(sub, r, p))
                moving += [(k, matmul(r, rk), [sum(r[i][m] * pk[m] for m in range(3)) + p[i] for i in range(3)])
                           for k, rk, pk in below]
            else:
                moving.append((j, rotation([0, 0, 0]), [0.0, 0.0, 0.0]))
        return combine(parts), moving

    def is_identity(r, p):
        return p == [0.0, 0.0, 0.0] and r == rotation([0, 0, 0])

    lines = [f"# {robot.get('name')} on a floating base, written by robots/floating/from_urdf.py",
             f"# from {urdf} (see robots/urdf/README.md for its provenance). Do not edit by hand.",
             f'name = "{robot.get("name")}"', "gravity = [0, 0, -9.81]   # in the world frame on a floating base", ""]
    base, moving = rigid(root)
    lines += ["[floating]   # " + root + " and the links fixed to it, in its frame"] + body_lines(base) + [""]
    queue = [(j, r, p, 0) for j, r, p in moving]
    while queue:
        j, r, p, parent = queue.pop(0)
        if not is_identity(r, p):
            sys.exit(f"joint {j.get('name')}: a moving joint below a fixed one is not written yet")
        kind = j.get("type")
        if kind not in ("revolute", "continuous", "prismatic"):
            sys.exit(f"joint {j.get('name')}: type {kind} is not written")
        o = j.find("origin")
        xyz, rpy = floats(o.get("xyz") if o is not None else None, [0, 0, 0]), floats(o.get("rpy") if o is not None else None, [0, 0, 0])
        axis = floats(j.find("axis").get("xyz") if j.find("axis") is not None else None, [1, 0, 0])
        child_body, below = rigid(j.find("child").get("link"))
        lines += ["[[joints]]", f'name = "{j.get("name")}"',
                  f'type = "{"prismatic" if kind == "prismatic" else "revolute"}"',
                  f"parent = {parent if parent == 0 else chr(34) + parent + chr(34)}",
                  f"origin = {{ xyz = {numbers(xyz)}, rpy = {numbers(rpy)} }}", f"axis = {numbers(axis)}"]
        lines += body_lines(child_body) + [""]
        # Depth first: this joint's children before its siblings.
        queue = [(k, rk, pk, j.get("name")) for k, rk, pk in below] + queue
    with open(out, "w") as f:
        f.write("\n".join(lines))


if __name__ == "__main__":
    main(*sys.argv[1:3])
