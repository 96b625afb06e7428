//! What the derive adds for reading: `equations()`, `equations_latex()` (and the hidden
//! constants `EQUATIONS`, `EQUATIONS_LATEX` they return), the equations in the rustdoc of
//! their impl, and the cap that keeps a large robot's derive fast. Run on the generator
//! library directly, as the proc macro does.

use dynamics_codegen::{derive_dynamics, front};
use quote::{format_ident, quote, ToTokens};
use std::time::Instant;

/// The impls in the derive's `const _: () = { … };` block.
fn impls(out: &syn::File) -> impl Iterator<Item = &syn::ItemImpl> {
    out.items
        .iter()
        .filter_map(|item| match item {
            syn::Item::Const(c) => match c.expr.as_ref() {
                syn::Expr::Block(b) => Some(&b.block.stmts),
                _ => None,
            },
            _ => None,
        })
        .flatten()
        .filter_map(|stmt| match stmt {
            syn::Stmt::Item(syn::Item::Impl(imp)) => Some(imp),
            _ => None,
        })
}

/// The `&'static str` literal assigned to `name` in the derive's output.
fn constant(out: &syn::File, name: &str) -> String {
    for imp in impls(out) {
        for it in &imp.items {
            if let syn::ImplItem::Const(k) = it {
                if k.ident == name {
                    if let syn::Expr::Lit(syn::ExprLit {
                        lit: syn::Lit::Str(s),
                        ..
                    }) = &k.expr
                    {
                        return s.value();
                    }
                }
            }
        }
    }
    panic!("no constant {name}");
}

/// The inherent impl that holds `EQUATIONS`.
fn equations_impl(out: &syn::File) -> &syn::ItemImpl {
    impls(out)
        .find(|imp| {
            imp.trait_.is_none()
                && imp
                    .items
                    .iter()
                    .any(|it| matches!(it, syn::ImplItem::Const(k) if k.ident == "EQUATIONS"))
        })
        .expect("no inherent impl")
}

/// The text of the `#[doc = "…"]` attributes, and whether one is `#[doc(hidden)]`.
fn doc_of(attrs: &[syn::Attribute]) -> (String, bool) {
    let mut doc = String::new();
    let mut hidden = false;
    for a in attrs.iter().filter(|a| a.path().is_ident("doc")) {
        match &a.meta {
            syn::Meta::NameValue(syn::MetaNameValue {
                value:
                    syn::Expr::Lit(syn::ExprLit {
                        lit: syn::Lit::Str(s),
                        ..
                    }),
                ..
            }) => doc.push_str(&s.value()),
            syn::Meta::List(l) => hidden |= l.tokens.to_string() == "hidden",
            _ => {}
        }
    }
    (doc, hidden)
}

/// The doc of the impl that holds `EQUATIONS`.
fn impl_doc(out: &syn::File) -> String {
    doc_of(&equations_impl(out).attrs).0
}

fn expand(input: proc_macro2::TokenStream) -> syn::File {
    let out = derive_dynamics(input);
    syn::parse2(out).expect("the derive's output parses")
}

#[test]
fn equations_in_constants_and_rustdoc() {
    let out = expand(quote! {
        #[dynamics(
            gravity = [0, -g, 0],
            dh = [[q, 0, l, 0]],
            link(mass = m, com = [-l / 2, 0, 0], inertia = [0, m * l * l / 12, m * l * l / 12, 0, 0, 0]),
        )]
        struct Rod { m: f64, l: f64, g: f64 }
    });
    let text = constant(&out, "EQUATIONS");
    let latex = constant(&out, "EQUATIONS_LATEX");
    assert!(text.contains("T1 = 1/3 m l² θ1'' + 1/2 m g l C1"), "{text}");
    assert!(latex.contains(r"\begin{align*}"), "{latex}");
    let doc = impl_doc(&out);
    assert!(doc.contains("The equations of motion of `Rod`"), "{doc}");
    // the text in a fenced block, so that rustdoc shows it as written
    assert!(doc.contains(&format!("```text\n{text}```")), "{doc}");
}

/// rustdoc prints a constant's whole value, escaped (`\u{3b8}`), on the type's page: the
/// constants are hidden, and documented functions return them.
#[test]
fn constants_hidden_behind_documented_functions() {
    let out = expand(quote! {
        #[dynamics(gravity = [0, -9.81, 0], dh = [[q, 0, l, 0]], link(mass = m))]
        struct Rod { m: f64, l: f64 }
    });
    let imp = equations_impl(&out);
    let mut seen = Vec::new();
    for item in &imp.items {
        match item {
            syn::ImplItem::Const(k) => {
                assert!(doc_of(&k.attrs).1, "{} is not hidden", k.ident);
                seen.push(k.ident.to_string());
            }
            syn::ImplItem::Fn(f) => {
                let (doc, hidden) = doc_of(&f.attrs);
                let name = f.sig.ident.to_string();
                assert!(
                    !hidden && doc.contains("equations of motion"),
                    "{name}: {doc}"
                );
                assert!(
                    f.sig.constness.is_some() && f.sig.inputs.is_empty(),
                    "{name}"
                );
                let body = f.block.to_token_stream().to_string();
                let constant = if name == "equations" {
                    "EQUATIONS"
                } else {
                    "EQUATIONS_LATEX"
                };
                assert_eq!(body, format!("{{ Self :: {constant} }}"), "{name}");
                seen.push(name);
            }
            _ => panic!("unexpected item"),
        }
    }
    seen.sort();
    assert_eq!(
        seen,
        [
            "EQUATIONS",
            "EQUATIONS_LATEX",
            "equations",
            "equations_latex"
        ]
    );
}

/// The 7-joint arm with its 70 inertial parameters as fields: the expansion of the readable
/// equations and kinematics is capped, the sections beyond the cap say so and point to `dynamics inspect`,
/// and the whole derive stays well under a second.
#[test]
fn large_robot_is_capped_and_fast() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../bench/robots/iiwa14_fields.toml"
    );
    let text = std::fs::read_to_string(path).expect("iiwa14_fields.toml");
    let robot = front::from_text(path, &text).expect("valid");
    let fields: Vec<_> = robot
        .fields()
        .iter()
        .map(|f| format_ident!("{f}"))
        .collect();
    assert_eq!(fields.len(), 70);
    let input = quote! {
        #[dynamics(file = "../bench/robots/iiwa14_fields.toml")]
        struct Iiwa { #(#fields: f64,)* }
    };
    let start = Instant::now();
    let out = derive_dynamics(input);
    let elapsed = start.elapsed();
    println!(
        "iiwa14_fields: derive in {:.1} ms",
        elapsed.as_secs_f64() * 1e3
    );
    let out: syn::File = syn::parse2(out).expect("parses");
    let text = constant(&out, "EQUATIONS");
    assert!(text.contains("too large to print here"), "{text}");
    assert!(text.contains("`dynamics inspect`"), "{text}");
    // what fits is printed: the gravity terms
    assert!(text.contains("  D2 = "), "{text}");
    // the kinematics too, each part on its own budget
    let in_hand = method_doc(&out, "hand_jacobian_in_hand").expect("a doc");
    assert!(
        in_hand.contains("`dynamics inspect --kinematics` command prints it"),
        "{in_hand}"
    );
    let pose = method_doc(&out, "hand_pose").expect("a doc");
    assert!(pose.contains("  nz = "), "{pose}");
    assert!(elapsed.as_secs_f64() < 1.0, "derive took {elapsed:?}");
}

/// The doc of the method `name` in the derive's `Dynamics` impl, if it has one.
fn method_doc(out: &syn::File, name: &str) -> Option<String> {
    let imp = impls(out).find(|imp| imp.trait_.is_some())?;
    imp.items.iter().find_map(|it| match it {
        syn::ImplItem::Fn(f) if f.sig.ident == name => {
            let (doc, _) = doc_of(&f.attrs);
            (!doc.is_empty()).then_some(doc)
        }
        _ => None,
    })
}

/// The hand pose and both Jacobians print in the rustdoc of their methods, in the book's
/// notation (the 3R arm of Niku's chapter 3 worked by hand: n = (C1 C23, S1 C23, S23),
/// px = C1 (a2 C2 + a3 C23), ᴴJ22 = a3 + a2 C3); the other methods keep the trait's docs.
#[test]
fn kinematics_in_the_rustdoc_of_their_methods() {
    let out = expand(quote! {
        #[dynamics(
            gravity = [0, 0, -g],
            dh = [[q, 0, 0, 90 deg], [q, 0, a2, 0], [q, 0, a3, 0]],
            link(mass = m1), link(mass = m2), link(mass = m3),
        )]
        struct Arm { m1: f64, m2: f64, m3: f64, a2: f64, a3: f64, g: f64 }
    });
    let pose = method_doc(&out, "hand_pose").expect("hand_pose has a doc");
    for line in [
        "  nx = C1 C23\n",
        "  ny = S1 C23\n",
        "  nz = S23\n",
        "  az = 0\n",
    ] {
        assert!(pose.contains(line), "{line} not in {pose}");
    }
    assert!(pose.contains("  px = C1(a2 C2 + a3 C23)\n"), "{pose}");
    assert!(pose.contains("```text\n"), "{pose}");
    assert!(!pose.contains("J11"), "{pose}");
    let in_base = method_doc(&out, "hand_jacobian_in_base").expect("a doc");
    assert!(in_base.contains("  J61 = 1\n"), "{in_base}");
    assert!(in_base.contains("  J33 = a3 C23\n"), "{in_base}");
    let in_hand = method_doc(&out, "hand_jacobian_in_hand").expect("a doc");
    assert!(in_hand.contains("  ᴴJ22 = a3 + a2 C3\n"), "{in_hand}");
    assert!(in_hand.contains("  ᴴJ41 = S23\n"), "{in_hand}");
    for other in ["mass_matrix", "link_poses", "joint_torques_for_hand_wrench"] {
        assert_eq!(method_doc(&out, other), None, "{other}");
    }
}
