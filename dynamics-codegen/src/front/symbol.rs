//! The keys of `#[dynamics(...)]` and of its `link(...)` entries, each set as one typed table:
//! the parser matches on the enum, and the table's names, in order, make the "expected one of"
//! list of an unknown key's error.

use syn::Ident;

/// An enum of keys with the name each is written as.
macro_rules! keys {
    ($(#[$doc:meta])* $name:ident { $($(#[$key_doc:meta])* $key:ident = $text:literal,)* }) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        pub(super) enum $name {
            $($(#[$key_doc])* $key,)*
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
    /// A key of `#[dynamics(...)]`.
    Key {
        /// `gravity = [gx, gy, gz]`.
        Gravity = "gravity",
        /// `dh = [[θ, d, a, α], ...]`.
        Dh = "dh",
        /// `link(...)`, one per joint.
        Link = "link",
        /// `convention = standard | modified`.
        Convention = "convention",
        /// `file = "robot.toml"`.
        File = "file",
        /// `name = "arm"`.
        Name = "name",
        /// `crate = "path::to::dynamics_runtime"`.
        Crate = "crate",
        /// `check_inertia = false`, for every link.
        CheckInertia = "check_inertia",
    }
}

keys! {
    /// A key of `link(...)`.
    LinkKey {
        /// `mass = m`.
        Mass = "mass",
        /// `com = [x, y, z]`.
        Com = "com",
        /// `inertia = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`.
        Inertia = "inertia",
        /// `actuator_inertia = I`.
        ActuatorInertia = "actuator_inertia",
        /// `spring = (stiffness, rest_position)`.
        Spring = "spring",
        /// `check_inertia = false`, for this link.
        CheckInertia = "check_inertia",
    }
}
