//! The struct's fields, which a robot's values may name: each named field must exist and be
//! of type `f32` or `f64`.

use super::errors::Errors;
use super::value::Spanned;
use syn::ext::IdentExt;

/// A struct field the values may name.
pub struct Field {
    /// Its name.
    pub name: String,
    /// Whether its type is `f32` or `f64`.
    pub is_float: bool,
    /// The struct's type parameter that is its type, if it is one (`l1: T`).
    pub generic: Option<String>,
}

/// The named fields of a struct.
#[must_use]
pub fn struct_fields(input: &syn::DeriveInput) -> Vec<Field> {
    let syn::Data::Struct(data) = &input.data else {
        return Vec::new();
    };
    let is = |ty: &syn::Type, name: &dyn Fn(&syn::Ident) -> bool| matches!(ty, syn::Type::Path(p) if p.qself.is_none() && p.path.get_ident().is_some_and(name));
    data.fields
        .iter()
        .filter_map(|f| {
            // `r#type` is the field the values name `type`.
            let name = f.ident.as_ref()?.unraw().to_string();
            let is_float = is(&f.ty, &|i| i == "f64" || i == "f32");
            let generic = input
                .generics
                .type_params()
                .find(|t| is(&f.ty, &|i| *i == t.ident))
                .map(|t| t.ident.to_string());
            Some(Field {
                name,
                is_float,
                generic,
            })
        })
        .collect()
}

/// What is wrong with naming field `name` in a value, if anything: the struct lacks it, or it
/// is not a float.
pub(super) fn field_error(name: &str, fields: &[Field]) -> Option<String> {
    match fields.iter().find(|f| f.name == name) {
        None => Some(format!(
            "`{name}` is not a field of this struct (values may name `f32` or `f64` fields)"
        )),
        Some(Field {
            generic: Some(t), ..
        }) => Some(format!(
            "field `{name}` has the generic type `{t}`: a field the description names must be of \
             type `f64` or `f32` (each generated method converts it to its own scalar type)"
        )),
        Some(f) if !f.is_float => Some(format!("field `{name}` must be of type `f64` or `f32`")),
        Some(_) => None,
    }
}

/// Errors, each on where it is written, for the fields `spanned` names that the struct lacks
/// or that are not floats.
pub(super) fn check_names(spanned: &Spanned, fields: &[Field], errors: &mut Errors) {
    for (name, span) in &spanned.fields {
        if let Some(message) = field_error(name, fields) {
            errors.push(*span, message);
        }
    }
}
