//! The words of the language, for completion in editors: the same tables
//! the compiler checks against, so the two cannot disagree.

/// Section names.
pub fn sections() -> &'static [&'static str] {
    &crate::lower::SECTIONS
}

/// The keys of `Globals`, aliases (`eye` for `from`) included.
pub fn global_keys() -> &'static [&'static str] {
    &crate::lower::GLOBAL_KEYS
}

/// The fields of a material in `BRDFs`.
pub fn material_fields() -> &'static [&'static str] {
    &crate::lower::MATERIAL_FIELDS
}

/// Object keywords of `Objects` (solids, predefined figures, aliases).
pub fn object_keywords() -> &'static [&'static str] {
    &crate::lower::OBJECT_KEYWORDS
}

/// `key = value` options an object statement may end with.
pub fn object_options() -> &'static [&'static str] {
    &crate::lower::OPTION_NAMES
}

/// Keywords of `Transformations`.
pub fn transformations() -> &'static [&'static str] {
    &crate::lower::TRANSFORMATIONS
}

/// `key = value` options of a light (an area light's radius and samples,
/// and the distance its colours are the irradiance at).
pub fn light_options() -> &'static [&'static str] {
    &crate::lower::LIGHT_OPTIONS
}

#[cfg(test)]
mod tests {
    #[test]
    fn tables_are_filled() {
        assert!(super::sections().contains(&"Points"));
        assert!(super::global_keys().contains(&"resolution"));
        assert!(super::global_keys().contains(&"eye"));
        assert!(super::light_options().contains(&"irradiance_at"));
        assert!(super::material_fields().contains(&"shininess"));
        assert!(super::object_keywords().contains(&"Sphere"));
        assert!(super::object_options().contains(&"wireframe"));
        assert!(super::transformations().contains(&"Rotate"));
        // The compiler accepts these light keys.
        let c = crate::compile(
            "Points { (0,0,0); (0,0,0.2); } Lights { %1, (1,1,1), (1,1,1), radius = 0.01, samples = 4; } \
             BRDFs { diffuse = (1,0,0); } Objects { Sphere %2, 0.05, #1; }",
        );
        assert!(!c.has_errors(), "{:?}", c.diagnostics);
    }
}
