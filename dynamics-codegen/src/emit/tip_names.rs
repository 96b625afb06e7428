//! The tips' names as the robot's associated constants: `TIP_NAMES`, in the order of the
//! `TipKinematics` results, and one index per tip named after it (`TIP_LEFT_HAND`).

use proc_macro2::{Ident, Span, TokenStream};
use quote::quote;

/// `pub const TIP_NAMES: [&str; TIPS]` and `pub const TIP_<NAME>: usize` for each tip, for the
/// robot's inherent impl.
pub(super) fn constants(names: &[String]) -> TokenStream {
    let count = names.len();
    let idents = index_names(names, "TIP");
    let indices = names
        .iter()
        .zip(&idents)
        .enumerate()
        .map(|(i, (name, ident))| {
            let doc = format!("The index of the tip `{name}` in the `TipKinematics` results.");
            quote! {
                #[doc = #doc]
                pub const #ident: usize = #i;
            }
        });
    quote! {
        /// The tips' names (the URDF's links, or `link{i}` after their joints), in the order of
        /// the `TipKinematics` results.
        pub const TIP_NAMES: [&'static str; #count] = [#(#names),*];
        #(#indices)*
    }
}

/// `{prefix}_` and the name in capitals, every other character than a letter or digit an
/// underscore (`link_3.0_tip` gives `TIP_LINK_3_0_TIP` for the prefix `TIP`); a name that
/// another already gives takes its index too (`TIP_A_B_2`), and none is `{prefix}_NAMES` or
/// `{prefix}_COUNT`.
#[doc(hidden)] // Public for the generator's tests (tests/it/unit).
pub fn index_names(names: &[String], prefix: &str) -> Vec<Ident> {
    let mut taken: Vec<String> = vec![format!("{prefix}_NAMES"), format!("{prefix}_COUNT")];
    names
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let upper: String = name
                .chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() {
                        c.to_ascii_uppercase()
                    } else {
                        '_'
                    }
                })
                .collect();
            let mut ident = format!("{prefix}_{upper}");
            if taken.contains(&ident) {
                ident = format!("{ident}_{i}");
            }
            taken.push(ident.clone());
            Ident::new(&ident, Span::call_site())
        })
        .collect()
}
