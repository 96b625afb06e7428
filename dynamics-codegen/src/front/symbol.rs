//! The keys of `#[dynamics(...)]` and of its `link(...)` entries, each set as one typed table:
//! the parser matches on the enum, and the table's names, in order, make the "expected one of"
//! list of an unknown key's error.

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
    /// `tool = [x, y, z, roll, pitch, yaw]`.
    Key {
        Gravity = "gravity", Dh = "dh", Link = "link", Convention = "convention",
        File = "file", Name = "name", Crate = "crate", CheckInertia = "check_inertia",
        Tool = "tool",
    }
}

keys! {
    /// A key of `link(...)`: `mass = m`, `com = [x, y, z]`,
    /// `inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`, `actuator_inertia = I`,
    /// `spring = (stiffness, rest_position)`, `check_inertia = false`.
    LinkKey {
        Mass = "mass", Com = "com", Inertia = "inertia",
        ActuatorInertia = "actuator_inertia", Spring = "spring", CheckInertia = "check_inertia",
    }
}
