//! Prints, for a description file, the expansion time, and per generated method its
//! operation counts and the size of its code.
//!
//! `cargo run --release -p dynamics-codegen --example stats -- tests/data/reference/robots/puma560.json`

use dynamics_codegen::{derive, generate, model};
use quote::quote;
use std::time::Instant;

fn main() {
    let mut args = std::env::args().skip(1);
    let Some(path) = args.next() else {
        eprintln!("usage: stats ROBOT.json|ROBOT.toml");
        std::process::exit(2);
    };
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let robot = model::from_text(&path, &text).unwrap_or_else(|e| panic!("{path}:{e}"));
    let start = Instant::now();
    let eq = derive(&robot);
    let krate = quote!(::dynamics_runtime);
    let fields = eq.fields.iter().map(|f| {
        let ident = proc_macro2::Ident::new(f, proc_macro2::Span::call_site());
        quote!(self.#ident)
    });
    let generated = generate(&eq, &krate, fields.collect());
    let methods = &generated.methods;
    let elapsed = start.elapsed();
    println!(
        "{}: {} joints, graph {} nodes, derived and emitted in {:.1} ms",
        robot.name,
        eq.dof,
        eq.graph.len(),
        elapsed.as_secs_f64() * 1e3
    );
    println!(
        "{:<18} {:>6} {:>6} {:>5} {:>5} {:>5} {:>7} {:>9}",
        "method", "mul", "add", "neg", "div", "trig", "flops", "bytes"
    );
    let mut total = 0;
    if let Some(c) = &generated.configuration {
        let bytes = c.tokens.to_string().len();
        total += bytes;
        println!(
            "{:<18} {:>42} {:>9}",
            "(configuration)", "shared: counted in each method", bytes
        );
    }
    for m in methods {
        let bytes = m.body.to_string().len();
        total += bytes;
        let o = m.ops;
        println!(
            "{:<18} {:>6} {:>6} {:>5} {:>5} {:>5} {:>7} {:>9}",
            m.name,
            o.mul,
            o.add,
            o.neg,
            o.div,
            o.trig,
            o.flops(),
            bytes
        );
    }
    println!("total generated code: {total} bytes");
}
