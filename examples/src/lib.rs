//! Examples of dynamics-runtime; see the `[[example]]` targets.
