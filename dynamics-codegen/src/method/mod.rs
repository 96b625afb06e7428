//! The typed table of the generated methods and their families: for each method, its name,
//! arguments, result, documentation, the book's equation and the names and docs of its output
//! elements; for each family, its trait, module and whether a robot must ask for it.
//!
//! The rows live in `dynamics-runtime/src/methods.rs`, `base_methods.rs`, `tip_methods.rs`,
//! `floating_methods.rs` and `results.rs`
//! (symlinked here), which
//! the runtime's traits and nalgebra wrappers are declared from, so the traits and the
//! generator cannot disagree. The table is data: which output of the traced equations a
//! method returns is the trace's to say (`Method::shape`).

include!("floating_methods.rs");
include!("tip_methods.rs");
include!("base_methods.rs");
include!("methods.rs");
include!("results.rs");

mod family;
// Before `declare_method`, which reads its `returns!`.
#[macro_use]
mod returns;

pub use family::FamilySet;
pub use returns::{Instance, Returns};

/// An argument of a generated method: `q`, `q̇` or `q̈`, each `&[T; N]` (a floating base's `q`
/// `&[T; Q]`, its `v` and `a` are `Qd` and `Qdd`), or a wrench `&[T; 6]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Argument {
    /// Joint positions.
    Q,
    /// Joint velocities.
    Qd,
    /// Joint accelerations.
    Qdd,
    /// A wrench `[fx, fy, fz, mx, my, mz]`.
    Wrench,
    /// A wrench at each tip, `&[[T; 6]; TIPS]`.
    Wrenches,
    /// Joint torques and forces.
    Tau,
}

impl Argument {
    /// The name the trait gives it: `q`, `qd`, `qdd`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Argument::Q => "q",
            Argument::Qd => "qd",
            Argument::Qdd => "qdd",
            Argument::Wrench => "wrench",
            Argument::Wrenches => "wrenches",
            Argument::Tau => "tau",
        }
    }
}

/// The `Argument` of a row's argument name.
macro_rules! argument {
    (q) => {
        Argument::Q
    };
    (qd) => {
        Argument::Qd
    };
    (qdd) => {
        Argument::Qdd
    };
    (v) => {
        Argument::Qd
    };
    (a) => {
        Argument::Qdd
    };
    (wrench) => {
        Argument::Wrench
    };
    (wrenches) => {
        Argument::Wrenches
    };
    (tau) => {
        Argument::Tau
    };
}

/// `enum Family`, `enum Method` and their accessors from the table's rows.
macro_rules! declare_method {
    ($(
        $(#[doc = $_trait_doc:literal])*
        trait $trait:ident<$config:ident $(, $space:ident)* $(; $($count:ident $(= $_count_default:ident)?),+)?> $(: $_supertrait:ident<$($_super_argument:ident),+>)?, nalgebra $_nalgebra:ident, batch $_batch:ident {
            items { $($_items:tt)* }
            $(
                $(#[doc = $family_doc:literal])*
                family $family:ident {
                    name: $family_name:ident,
                    module: $module:literal,
                    opt_in: $opt_in:literal,
                    adjective: $adjective:literal,
                }
                methods {$(
                    $(#[doc = $doc:literal])*
                    fn $name:ident($($argument:ident),*) -> $result:ident, nalgebra $_wrapper:ident $(, batch $_batch_fn:ident)? {
                        variant: $variant:ident,
                        equation: $equation:expr,
                        prefix: $prefix:literal,
                        summary: $summary:literal,
                        element: $element:literal,
                        $(diagonal: $diagonal:literal,)?
                        $(default: $default:ident,)?
                        $(compiled_apart: $apart:literal,)?
                        $(into: $into:ident,)?
                    }
                )*}
            )*
        }
    )*) => {
        /// A family of methods, emitted in a module of its own with its own shared
        /// configuration and motion functions, so that code calling one family's methods never
        /// inlines another's: a controller that calls only `inverse_dynamics` compiles none of
        /// the kinematics.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub enum Family {
            $($($(#[doc = $family_doc])* $family,)*)*
        }

        impl Family {
            /// Every family, in the order the derive emits their modules.
            pub const ALL: &'static [Family] = &[$($(Family::$family),*),*];

            /// Its name: the attribute's key that asks for an opt-in family
            /// (`derivatives = true`), the command line's `--with derivatives`.
            #[must_use]
            pub fn name(self) -> &'static str {
                match self { $($(Family::$family => stringify!($family_name),)*)* }
            }

            /// The runtime trait its methods belong to.
            #[must_use]
            pub fn trait_name(self) -> &'static str {
                match self { $($(Family::$family => stringify!($trait),)*)* }
            }

            /// The names of its trait's const parameters after the configuration's and the
            /// velocity's lengths, counts of its own (the base parameters' `B`, the links'
            /// `LINKS`), in order.
            #[must_use]
            pub fn count_parameters(self) -> &'static [&'static str] {
                match self.trait_name() {
                    $(name if name == stringify!($trait) => &[$($(stringify!($count)),+)?],)*
                    _ => &[],
                }
            }

            /// Whether its trait is a floating base's, whose configuration (`Q`, its first const
            /// parameter) is longer than its velocity (`N`): `FloatingDynamics<Q, N>`.
            #[must_use]
            pub fn is_floating(self) -> bool {
                match self.trait_name() {
                    $(name if name == stringify!($trait) => stringify!($config) != "N",)*
                    _ => false,
                }
            }

            /// Whether the derive writes it only for a robot that asks for it.
            #[must_use]
            pub fn is_opt_in(self) -> bool {
                match self { $($(Family::$family => $opt_in,)*)* }
            }

            /// The name of the module holding its generated functions.
            #[must_use]
            pub fn module(self) -> &'static str {
                match self { $($(Family::$family => $module,)*)* }
            }

            /// How `dynamics stats` names its shared functions: `(kinematic configuration)`.
            #[must_use]
            pub fn adjective(self) -> &'static str {
                match self { $($(Family::$family => $adjective,)*)* }
            }
        }

        /// A method of the runtime's traits.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub enum Method {
            $($($($(#[doc = $doc])* $variant,)*)*)*
        }

        impl Method {
            /// Every method, in the traits' order.
            pub const ALL: &'static [Method] = &[$($($(Method::$variant),*),*),*];

            /// Its name, e.g. `mass_matrix`.
            #[must_use]
            pub fn name(self) -> &'static str {
                match self { $($($(Method::$variant => stringify!($name),)*)*)* }
            }

            /// Its family, whose module it goes to.
            #[must_use]
            pub fn family(self) -> Family {
                match self { $($($(Method::$variant => Family::$family,)*)*)* }
            }

            /// Whether its function is compiled once, apart from the code that calls it
            /// (`compiled_apart: true` in its row): `#[inline(never)]`, in its family's module
            /// beside the struct, a codegen unit of its own, compiled in parallel with the
            /// rest.
            #[must_use]
            pub fn is_compiled_apart(self) -> bool {
                match self { $($($(Method::$variant => false $(|| $apart)?,)*)*)* }
            }

            /// The name of its method writing the result into the caller's `&mut`
            /// (`into: regressor_into` in its row), if it has one.
            #[must_use]
            pub fn in_place_name(self) -> Option<&'static str> {
                match self { $($($(Method::$variant => None $(.or(Some(stringify!($into))))?,)*)*)* }
            }

            /// Its arguments' names in its trait, in order (a floating base's `v`, `a`).
            #[must_use]
            pub fn argument_names(self) -> &'static [&'static str] {
                match self { $($($(Method::$variant => &[$(stringify!($argument)),*],)*)*)* }
            }

            /// Its arguments, in order.
            #[must_use]
            pub fn arguments(self) -> &'static [Argument] {
                match self { $($($(Method::$variant => &[$(argument!($argument)),*],)*)*)* }
            }

            /// The shape of its result.
            #[must_use]
            pub fn returns(self) -> Returns {
                match self { $($($(Method::$variant => returns!($result),)*)*)* }
            }

            /// The trait method's documentation.
            #[must_use]
            pub fn doc(self) -> &'static str {
                match self { $($($(Method::$variant => concat!($($doc, "\n"),*),)*)*)* }
            }

            /// A one-line summary, e.g. `g(q), with joint springs.`
            #[must_use]
            pub fn summary(self) -> &'static str {
                match self { $($($(Method::$variant => $summary,)*)*)* }
            }

            /// The number of its equation in Niku, *Introduction to Robotics*, ch. 6.
            #[must_use]
            pub fn equation(self) -> Option<&'static str> {
                match self { $($($(Method::$variant => $equation,)*)*)* }
            }

            /// The prefix of its output elements' names (`m` gives `m1_2`, `tau` gives `tau3`).
            #[must_use]
            pub fn prefix(self) -> &'static str {
                match self { $($($(Method::$variant => $prefix,)*)*)* }
            }

            /// Whether the trait gives it a body (zeros), for a term a robot may not have: the
            /// derive then writes it only for a robot that has the term.
            #[must_use]
            pub fn has_default(self) -> bool {
                match self {
                    $($($(Method::$variant => None::<&str> $(.or(Some(stringify!($default))))?.is_some(),)*)*)*
                }
            }

            /// The doc template of an element, on the diagonal or not (`{i}`, `{j}`,
            /// `{equation}` to fill in).
            #[doc(hidden)] // Public for the generator's tests (tests/it/unit).
            pub fn element_template(self, diagonal: bool) -> &'static str {
                match self {
                    $($($(Method::$variant => {
                        let on_diagonal: Option<&'static str> = None $(.or(Some($diagonal)))?;
                        match on_diagonal {
                            Some(template) if diagonal => template,
                            _ => $element,
                        }
                    })*)*)*
                }
            }
        }
    };
}

for_each_method!(declare_method);

impl Method {
    /// Whether its result is always written in place (`into` in its row), its by-value form
    /// calling that function on zeros: the regressors. `M`'s `_into` (a fixed or a floating
    /// base's) is written so only where it is computed apart and stored element by element, a
    /// tree's (elsewhere the trait's default copies the by-value result).
    #[must_use]
    pub fn always_in_place(self) -> bool {
        self.in_place_name().is_some() && !self.is_mass_matrix()
    }

    /// Whether it is a mass matrix `M(q)`, of a fixed or a floating base.
    #[must_use]
    pub fn is_mass_matrix(self) -> bool {
        matches!(self, Method::MassMatrix | Method::FloatingMassMatrix)
    }

    /// The method called `name` of a fixed base (a floating base's have the same names:
    /// [`Method::from_name_on`]).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Method> {
        Method::from_name_on(name, false)
    }

    /// The method called `name` of a floating base (`floating`) or of a fixed one.
    #[must_use]
    pub fn from_name_on(name: &str, floating: bool) -> Option<Method> {
        let on = |m: &Method| m.family().is_floating() == floating;
        Method::ALL
            .iter()
            .copied()
            .filter(on)
            .find(|m| m.name() == name)
    }

    /// What element `(i, j)` (from 0; `j` 0 for a vector, both for a scalar) is, in the
    /// book's terms: short and ASCII, since a large robot has a hundred of them and non-ASCII
    /// text is escaped in tokens.
    #[must_use]
    pub fn describe(self, i: usize, j: usize) -> String {
        self.describe_in(0, i, j)
    }

    /// [`Method::describe`] of element `(i, j)` of the `k`-th matrix (from 0) of a stack of
    /// them (`link_poses`).
    #[must_use]
    pub fn describe_in(self, k: usize, i: usize, j: usize) -> String {
        use std::fmt::Write as _;
        let diagonal = self.returns() == Returns::Matrix && i == j;
        // One pass, each `{key}` written in place: five `replace`s made five strings, for each
        // of the thousands of output elements a derive names.
        let mut rest = self.element_template(diagonal);
        let mut text = String::with_capacity(rest.len() + 8);
        while let Some((before, after)) = rest.split_once('{') {
            text.push_str(before);
            let Some((key, next)) = after.split_once('}') else {
                text.push('{');
                rest = after;
                break;
            };
            let index = |n: usize| n + 1;
            let _ = match key {
                "k" => write!(text, "{}", index(k)),
                "i" => write!(text, "{}", index(i)),
                "j" => write!(text, "{}", index(j)),
                "x" => text.write_str(self.arguments().get(k).map_or("", |a| a.name())),
                "equation" => text.write_str(self.equation().unwrap_or_default()),
                _ => write!(text, "{{{key}}}"),
            };
            rest = next;
        }
        text.push_str(rest);
        text
    }
}
