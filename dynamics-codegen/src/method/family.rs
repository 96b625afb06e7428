//! What a family of methods decides beyond its row, and the set of opt-in families a robot
//! asks for ([`FamilySet`]), which travels from the attribute (or the command line) to the
//! trace and the emission in place of one flag per family.

use super::{Family, Method};

impl Family {
    /// Whether its module goes beside the struct, named after it, rather than in the derive's
    /// `const _` block: where it holds a method compiled apart ([`Method::is_compiled_apart`]),
    /// since a module inside that block shares the codegen unit of the code around it.
    #[must_use]
    pub fn is_beside_the_struct(self) -> bool {
        Method::ALL
            .iter()
            .any(|m| m.family() == self && m.is_compiled_apart())
    }

    /// The family named `name` (`derivatives`): a fixed base's, which the attribute and the
    /// command line name (a floating base's opt-in family answers the same name:
    /// [`Family::on_floating_base`]).
    #[must_use]
    pub fn from_name(name: &str) -> Option<Family> {
        let fixed = Family::ALL.iter().filter(|f| !f.is_floating());
        fixed.copied().find(|f| f.name() == name)
    }

    /// The floating base's family that answers this one's name where a robot with `base =
    /// floating` asks for it (`derivatives = true`: `FloatingDerivatives`), if any.
    #[must_use]
    pub fn on_floating_base(self) -> Option<Family> {
        let floating = Family::ALL.iter().filter(|f| f.is_floating());
        floating.copied().find(|f| f.name() == self.name())
    }

    /// The opt-in families' names, for a message: `derivatives` (each once: a floating base's
    /// answer a fixed base's names).
    #[must_use]
    pub fn opt_in_names() -> Vec<&'static str> {
        let opt_in = Family::ALL
            .iter()
            .filter(|f| f.is_opt_in() && !f.is_floating());
        opt_in.map(|f| f.name()).collect()
    }

    fn bit(self) -> u32 {
        1 << (self as u32)
    }
}

/// The families a robot has: every family that is not opt-in, and the opt-in ones it asks for
/// (`derivatives = true`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct FamilySet {
    bits: u32,
}

impl Default for FamilySet {
    /// The families every robot on a fixed base has.
    fn default() -> FamilySet {
        FamilySet::always(false)
    }
}

impl FamilySet {
    /// The families every robot on a floating base has (`FloatingDynamics`'s).
    #[must_use]
    pub fn floating() -> FamilySet {
        FamilySet::always(true)
    }

    /// The families that are not opt-in, of a floating base or of a fixed one.
    fn always(floating: bool) -> FamilySet {
        let always = Family::ALL
            .iter()
            .filter(|f| !f.is_opt_in() && f.is_floating() == floating);
        FamilySet {
            bits: always.fold(0, |bits, f| bits | f.bit()),
        }
    }

    /// This set with `family` too.
    #[must_use]
    pub fn with(self, family: Family) -> FamilySet {
        FamilySet {
            bits: self.bits | family.bit(),
        }
    }

    /// This set without `family`.
    #[must_use]
    pub fn without(self, family: Family) -> FamilySet {
        FamilySet {
            bits: self.bits & !family.bit(),
        }
    }

    /// Whether it holds `family`.
    #[must_use]
    pub fn contains(self, family: Family) -> bool {
        self.bits & family.bit() != 0
    }

    /// Whether it holds `method`'s family.
    #[must_use]
    pub fn has(self, method: Method) -> bool {
        self.contains(method.family())
    }

    /// The opt-in families it holds, in the table's order.
    pub fn opt_in(self) -> impl Iterator<Item = Family> {
        let asked = move |f: &Family| f.is_opt_in() && self.contains(*f);
        Family::ALL.iter().copied().filter(asked)
    }
}
