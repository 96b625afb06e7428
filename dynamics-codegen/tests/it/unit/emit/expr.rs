use dynamics_codegen::emit::expr::{
    array, binary, block, call, let_statement, mul_add, negate, parenthesized, raw_string,
};
use dynamics_codegen::emit::plan::{Function, Operator};
use proc_macro2::TokenStream;
use quote::quote;

/// Each form as `quote!` writes it, token for token (the text of a stream shows its
/// tokens' spacing and groups): nested, so that the operands are streams built the same
/// way.
#[test]
fn the_forms_are_the_tokens_quote_writes() {
    let (a, b, c) = (quote!(a), quote!(t12), quote!(T::ONE));
    let moved = mul_add(
        negate(binary(a.clone(), Operator::Sub, b.clone())),
        call(Function::Cos, binary(b.clone(), Operator::Div, c.clone())),
        TokenStream::from(parenthesized(binary(c.clone(), Operator::Mul, a.clone()))),
    );
    let quoted = quote!(-#a - #b.mul_add(T::cos(#b / #c), (#c * #a)));
    assert_eq!(moved.to_string(), quoted.to_string());
    for (f, q) in [
        (Function::Sin, quote!(T::sin(a))),
        (Function::Tanh, quote!(T::tanh(a))),
        (Function::Sign, quote!(T::sign(a))),
    ] {
        assert_eq!(call(f, quote!(a)).to_string(), q.to_string());
    }
    assert_eq!(
        binary(quote!(a), Operator::Add, quote!(-b)).to_string(),
        quote!(a + -b).to_string()
    );
    let items = [quote!(a), quote!(b + c), quote!([d])];
    let arrays = [array(items.clone()), array([]), array([quote!(a)])];
    let quoted = [quote!([#(#items),*]), quote!([]), quote!([a])];
    for (built, quoted) in arrays.iter().zip(&quoted) {
        assert_eq!(built.to_string(), quoted.to_string());
    }
    assert_eq!(
        block(quote!(a; b)).to_string(),
        quote!({
            a;
            b
        })
        .to_string()
    );
    let name = proc_macro2::Ident::new("t1", proc_macro2::Span::call_site());
    assert_eq!(
        let_statement(&name, quote!(a * b)).to_string(),
        quote!(let t1 = a * b;).to_string()
    );
}

/// A raw string literal holds the text as it is, with enough `#`s that no quote in it ends
/// the literal; a text it cannot hold (a bare carriage return) is escaped instead.
#[test]
fn raw_strings_hold_any_text() {
    for text in [
        "",
        "plain text, θ̈ and ∂τ/∂q",
        "a \"quoted\" word",
        "ends in a quote\"",
        "\"# and \"## inside",
        "a backslash \\ and a\nnew line",
        "a bare \r return",
    ] {
        let literal = raw_string(text);
        let parsed: syn::LitStr = syn::parse2(quote!(#literal)).expect("a string literal");
        assert_eq!(parsed.value(), text);
    }
    assert!(raw_string("x\"#y").to_string().starts_with("r##\""));
}
