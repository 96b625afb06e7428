"""A URDF's kinematic tree as the project's front end walks it (for `make.py`): the moving
joints depth first from the root link, a link's child joints in the file's order of their
`<joint>` elements, fixed joints walked through; and Pinocchio's order (the same walk with a
link's child joints sorted by name: urdfdom keeps the joints in a name-keyed std::map)."""

MOVING = ("revolute", "continuous", "prismatic")


def _parent(joint):
    return joint.find("parent").get("link")


def _child(joint):
    return joint.find("child").get("link")


def _root(root):
    children = {_child(j) for j in root.findall("joint")}
    roots = [link.get("name") for link in root.findall("link") if link.get("name") not in children]
    assert len(roots) == 1, f"roots: {roots}"
    return roots[0]


def _walk(root, key):
    """The moving joints (elements) depth first, a link's child joints sorted by `key`; each
    one's parent (index of the nearest moving ancestor, None for the base); each link's body
    (index of the moving joint that carries it, None for the base's rigid body)."""
    below = {}
    for position, j in enumerate(root.findall("joint")):
        below.setdefault(_parent(j), []).append((position, j))
    joints, parents, body = [], [], {}

    def visit(link, owner):
        assert link not in body, f"{link} has two parents or closes a cycle"
        body[link] = owner
        for _, j in sorted(below.get(link, []), key=key):
            if j.get("type") in MOVING:
                joints.append(j)
                parents.append(owner)
                visit(_child(j), len(joints) - 1)
            else:
                assert j.get("type") == "fixed", f"{j.get('name')}: {j.get('type')} joint"
                visit(_child(j), owner)

    visit(_root(root), None)
    return joints, parents, body


def pinocchio_rule_order(root):
    """The joint names in the order Pinocchio's URDF loader gives them."""
    joints, _, _ = _walk(root, key=lambda pj: pj[1].get("name"))
    return [j.get("name") for j in joints]


class Tree:
    """The moving tree of a URDF (an ElementTree root), in the front end's order."""

    def __init__(self, root):
        self.root = _root(root)
        joints, self.parents, self.body = _walk(root, key=lambda pj: pj[0])
        self.names = [j.get("name") for j in joints]
        self.types = [j.get("type") for j in joints]
        self.limits = []
        for j in joints:
            lim = j.find("limit")
            bounded = j.get("type") != "continuous" and lim is not None and (
                lim.get("lower") is not None or lim.get("upper") is not None)
            self.limits.append((float(lim.get("lower", 0)), float(lim.get("upper", 0))) if bounded else None)
        # index of the mimicking joint: (index of the joint it follows, multiplier, offset)
        self.mimic = {}
        for i, j in enumerate(joints):
            m = j.find("mimic")
            if m is not None:
                self.mimic[i] = (self.names.index(m.get("joint")), float(m.get("multiplier", 1.0)),
                                 float(m.get("offset", 0.0)))
        n = len(self.names)
        ancestors = []
        for i in range(n):
            up, p = set(), self.parents[i]
            while p is not None:
                up.add(p)
                p = self.parents[p]
            ancestors.append(up)
        self.related = [[i == k or i in ancestors[k] or k in ancestors[i] for k in range(n)] for i in range(n)]

    def structure(self):
        """Names, parents, limits and the ancestor relation of every moving joint."""
        return self.names, self.parents, self.limits, self.related
