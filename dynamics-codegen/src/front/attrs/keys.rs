//! The keys of `#[dynamics(...)]` and of its `link(...)` entries, each set as one typed table:
//! the parser matches on the enum, and the table's names, in order, make the "expected one of"
//! list of an unknown key's error.

use crate::method::Family;
use syn::Ident;

/// An enum of keys with the name each is written as.
macro_rules! keys {
    ($(#[$doc:meta])* $name:ident { $($key:ident = $text:literal,)* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub(super) enum $name {
            $($key,)*
        }

        impl $name {
            /// Every key, in the order error messages list them.
            const ALL: &'static [$name] = &[$($name::$key,)*];
            /// Every key's name, in the order of [`Self::ALL`].
            pub(super) const NAMES: &'static [&'static str] = &[$($text,)*];

            /// How the key is written.
            pub(super) fn name(self) -> &'static str {
                match self {
                    $($name::$key => $text,)*
                }
            }

            /// The key `ident` names, if any.
            pub(super) fn find(ident: &Ident) -> Option<$name> {
                Self::ALL.iter().copied().find(|key| *ident == key.name())
            }
        }
    };
}

keys! {
    /// A key of `#[dynamics(...)]`: `gravity = [gx, gy, gz]`, `dh = [[θ, d, a, α], ...]`,
    /// `link(...)` (one per joint), `convention = standard | modified`, `file = "robot.toml"`,
    /// `name = "arm"`, `crate = "path::to::dynamics_runtime"`, `check_inertia = false`,
    /// `joints = [revolute(..), prismatic(..), ...]` (joints by placements and axes),
    /// `urdf = "robots/ur10.urdf"` with `base = "base_link"` and `tip = "tool0"` (a chain) or
    /// `tips = ["left_hand", "right_hand"]` (the branches to those links),
    /// `tool = [x, y, z, roll, pitch, yaw]`, `contacts = true` (a floating base's contact terms
    /// in closed form). An opt-in family's name is a key too
    /// (`derivatives = true`), from the method table.
    Key {
        Gravity = "gravity", Dh = "dh", Link = "link", Convention = "convention",
        File = "file", Name = "name", Crate = "crate", CheckInertia = "check_inertia",
        Joints = "joints", Urdf = "urdf", Base = "base", Tip = "tip", Tips = "tips",
        Tool = "tool", Contacts = "contacts",
    }
}

keys! {
    /// An entry of `joints = [...]`: `revolute(..)` or `prismatic(..)`.
    JointType {
        Revolute = "revolute", Prismatic = "prismatic",
    }
}

keys! {
    /// A key of `revolute(...)` and `prismatic(...)`: `xyz = [x, y, z]` and
    /// `rpy = [roll, pitch, yaw]` place the joint frame in the parent link's frame (as URDF's
    /// `<origin>`), `axis = [x, y, z]` is the unit axis in the joint frame; in a tree,
    /// `parent = 2` or `parent = "palm"` names the joint it hangs from (default: the one
    /// before; 0 the base) and `name = "palm"` names it; `mimic = (joint = 2, multiplier = k,
    /// offset = o)` makes it follow joint 2 (`q = k q_2 + o`), not a coordinate.
    JointKey {
        Xyz = "xyz", Rpy = "rpy", Axis = "axis", Parent = "parent", Name = "name",
        Mimic = "mimic",
    }
}

keys! {
    /// A key of `link(...)`: `mass = m`, `com = [x, y, z]`,
    /// `inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`, `actuator_inertia = I`,
    /// `spring = (stiffness, rest_position)`, `check_inertia = false`,
    /// `friction = (viscous = .., ...)`, `rotor_inertia = I`, `gear_ratio = N`.
    LinkKey {
        Mass = "mass", Com = "com", Inertia = "inertia",
        ActuatorInertia = "actuator_inertia", Spring = "spring", CheckInertia = "check_inertia",
        Friction = "friction", RotorInertia = "rotor_inertia", GearRatio = "gear_ratio",
    }
}

keys! {
    /// A key of `friction = (...)`: `f_v q̇ + f_c sign(q̇) + f_0`, `sign` as `tanh(q̇ / ε)` with
    /// a smoothing velocity ε.
    FrictionKey {
        Viscous = "viscous", Coulomb = "coulomb", Offset = "offset", Smoothing = "smoothing",
    }
}

/// Every word the attribute's keys are written with, table after table: what a fuzzer
/// mutating attributes should draw from, so that a new key is fuzzed as soon as it exists.
pub fn attribute_words() -> impl Iterator<Item = &'static str> {
    [
        Key::NAMES,
        JointType::NAMES,
        JointKey::NAMES,
        LinkKey::NAMES,
        FrictionKey::NAMES,
    ]
    .into_iter()
    .flatten()
    .copied()
    .chain(Family::opt_in_names())
}
