//! What the derive adds for reading: `EQUATIONS`, `EQUATIONS_LATEX` and the equations in the
//! rustdoc of their impl, and the cap that keeps a large robot's derive fast. Run on the
//! generator library directly, as the proc macro does.

use dynamics_codegen::{derive_dynamics, front};
use quote::{format_ident, quote};
use std::time::Instant;

/// The `&'static str` literal assigned to `name` in the derive's output.
fn constant(out: &syn::File, name: &str) -> String {
    for item in &out.items {
        let syn::Item::Const(c) = item else { continue };
        let syn::Expr::Block(b) = c.expr.as_ref() else {
            continue;
        };
        for stmt in &b.block.stmts {
            let syn::Stmt::Item(syn::Item::Impl(imp)) = stmt else {
                continue;
            };
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
    }
    panic!("no constant {name}");
}

/// The doc of the impl that holds `EQUATIONS`.
fn impl_doc(out: &syn::File) -> String {
    for item in &out.items {
        let syn::Item::Const(c) = item else { continue };
        let syn::Expr::Block(b) = c.expr.as_ref() else {
            continue;
        };
        for stmt in &b.block.stmts {
            let syn::Stmt::Item(syn::Item::Impl(imp)) = stmt else {
                continue;
            };
            let holds_equations = imp
                .items
                .iter()
                .any(|it| matches!(it, syn::ImplItem::Const(k) if k.ident == "EQUATIONS"));
            if imp.trait_.is_some() || !holds_equations {
                continue;
            }
            let mut doc = String::new();
            for a in &imp.attrs {
                if let syn::Meta::NameValue(nv) = &a.meta {
                    if nv.path.is_ident("doc") {
                        if let syn::Expr::Lit(syn::ExprLit {
                            lit: syn::Lit::Str(s),
                            ..
                        }) = &nv.value
                        {
                            doc.push_str(&s.value());
                        }
                    }
                }
            }
            return doc;
        }
    }
    panic!("no inherent impl");
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
    assert!(text.contains("T1 = 1/3 m l² θ̈1 + 1/2 m g l C1"), "{text}");
    assert!(latex.contains(r"\begin{align*}"), "{latex}");
    let doc = impl_doc(&out);
    assert!(doc.contains("The equations of motion of `Rod`"), "{doc}");
    // the text in a fenced block, so that rustdoc shows it as written
    assert!(doc.contains(&format!("```text\n{text}```")), "{doc}");
}

/// The 7-joint arm with its 70 inertial parameters as fields: the expansion of the readable
/// equations is capped, the sections beyond the cap say so and point to `dynamics inspect`,
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
    assert!(elapsed.as_secs_f64() < 1.0, "derive took {elapsed:?}");
}
