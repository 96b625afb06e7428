//! `dynamics emit ROBOT`: a standalone Rust module with the code the derive generates, or
//! (`--lang c`) a header-only C file of the same equations; with the simplified models where
//! the description file asks for them (`[simplify]`), each function's proven bounds in its
//! comment.

use super::{eval, load_with_request, simplification, Failure};
use crate::args::{Emit, Lang};
use dynamics_codegen::pipeline::FloatingC;

/// The C header of the robot of `args`, as the front door writes it.
fn c_header(args: &Emit) -> Result<String, Failure> {
    let loaded = load_with_request(&args.robot)?;
    let simplify = simplification(&loaded, &[], "emit")?;
    let header = loaded
        .c_header(
            args.families.set(),
            simplify.as_ref(),
            args.prefix.as_deref(),
        )
        .map_err(|d| Failure::File(d.to_string()))?;
    Ok(header.text)
}

/// `--floating`: the C header of the robot on a free-flying base.
fn floating_c_header(args: &Emit) -> Result<String, Failure> {
    let loaded = load_with_request(&args.robot)?;
    let extra = FloatingC {
        kinematics: args.kinematics,
        contacts: args.contacts,
        configuration: args.configuration,
    };
    let header = loaded
        .floating_c_header_with(args.families.set(), extra, args.prefix.as_deref())
        .map_err(|d| {
            let lines: Vec<String> = d.iter().map(ToString::to_string).collect();
            Failure::File(lines.join("\ndynamics: "))
        })?;
    Ok(header.text)
}

pub fn run(args: &Emit) -> Result<String, Failure> {
    if args.floating && args.lang != Lang::C {
        let message = "--floating emits the C header (--lang c): the derive's `base = floating` \
                       writes the Rust";
        return Err(eval::usage("emit", message));
    }
    if args.floating {
        return floating_c_header(args);
    }
    if args.lang == Lang::C {
        return c_header(args);
    }
    if args.prefix.is_some() {
        let message = "--prefix names the C functions: it needs --lang c";
        return Err(eval::usage("emit", message));
    }
    let loaded = load_with_request(&args.robot)?;
    let simplify = simplification(&loaded, &[], "emit")?;
    let module = loaded
        .rust_module(args.families.set(), simplify.as_ref())
        .map_err(|d| Failure::File(d.to_string()))?;
    // Tokens that do not parse are a bug of the generator: an error, never code that does not
    // compile (as `pub struct Self;` once was).
    let file = syn::parse2::<syn::File>(module.items).map_err(|e| {
        Failure::File(format!(
            "{}: the generated Rust does not parse ({e}): a bug of `dynamics emit`",
            args.robot.path
        ))
    })?;
    Ok(format!(
        "{}\n{}",
        module.header,
        prettyplease::unparse(&file)
    ))
}
