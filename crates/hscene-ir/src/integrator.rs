//! Which way of computing light a scene asks for (`integrator = NAME;`);
//! the renderer holds the integrators themselves.

/// An integrator, by name.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum IntegratorKind {
    /// Whitted's recursive ray tracing with the thesis's Phong model: point
    /// and spherical area lights, an `ambient` constant, mirror reflection
    /// and refraction, shadow rays that pass through glass.
    #[default]
    Whitted,
    /// An unbiased path tracer of H³: light bounces between surfaces,
    /// lights and emissive surfaces are sampled with multiple importance
    /// sampling, glass is a dielectric with Fresnel.
    Path,
}

impl IntegratorKind {
    /// Every integrator with its name, as `integrator = NAME;` and
    /// `--integrator NAME` spell it.
    pub const ALL: [(IntegratorKind, &'static str); 2] = [
        (IntegratorKind::Whitted, "whitted"),
        (IntegratorKind::Path, "path"),
    ];

    /// Its name.
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(k, _)| *k == self)
            .map_or("", |(_, n)| n)
    }

    /// The integrator called `name`, if there is one.
    pub fn from_name(name: &str) -> Option<IntegratorKind> {
        Self::ALL.iter().find(|(_, n)| *n == name).map(|(k, _)| *k)
    }

    /// The names, for messages: `whitted, path`.
    pub fn names() -> String {
        Self::ALL.map(|(_, n)| n).join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for (kind, name) in IntegratorKind::ALL {
            assert_eq!(kind.name(), name);
            assert_eq!(IntegratorKind::from_name(name), Some(kind));
        }
        assert_eq!(IntegratorKind::from_name("Whitted"), None);
        assert_eq!(IntegratorKind::names(), "whitted, path");
        // A new kind fails to compile here until it has its row in `ALL`.
        match IntegratorKind::default() {
            IntegratorKind::Whitted | IntegratorKind::Path => {}
        }
    }
}
