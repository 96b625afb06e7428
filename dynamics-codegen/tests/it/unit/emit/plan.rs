use dynamics_codegen::emit::plan::{needs_parentheses, Place, Precedence};

/// The table, against the places' meanings: `a - (b + c)`, `(a + b) * c`, `a * (b * c)`,
/// `a + (-b)`, `a * (-b)`, `-(-a)`, but `a + b * c`, `-a * b`, `a * b * c` as written.
#[test]
fn parentheses_only_where_the_order_or_a_sign_needs_them() {
    use Place::{AddLeft, AddRight, MulLeft, MulRight, Top};
    use Precedence::{Atom, Prefix, Product, Sum};
    let wrapped = [
        (Sum, AddRight),
        (Sum, MulLeft),
        (Sum, MulRight),
        (Product, MulRight),
        (Prefix, AddRight),
        (Prefix, MulRight),
    ];
    for p in [Sum, Product, Prefix, Atom] {
        for place in [Top, AddLeft, AddRight, MulLeft, MulRight] {
            assert_eq!(
                needs_parentheses(p, place),
                wrapped.contains(&(p, place)),
                "{p:?} at {place:?}"
            );
        }
    }
}
