//! The scenario's two-material conductor: `conductor.tension_law = "two_material"` takes the axial law of
//! the catalogue conductor named by `conductor.catalog` ([`crate::thermal::catalog::CatalogConductor::two_material`]:
//! each material's published stress-strain polynomial, final modulus and expansion, data/conductors.toml,
//! docs/conductors.md), virgin on the curve `conductor.curve` ("initial", the default: as strung; or
//! "creep": after the long-term creep of the published 10-year curve). The run then follows
//! [`crate::wire::material`].

use super::schema::{ConductorSpec, CurveSpec, TensionLawSpec};
use super::validate::Check;
use crate::conductor::{CurveKind, TwoMaterial};

/// The two-material law and curve of the scenario's conductor, or `None` for the other laws (and where a
/// problem was recorded: a two-material law without a catalogue conductor that has stress-strain data, a
/// creep curve the conductor does not have, a curve with another law).
pub fn check(c: &mut Check, cd: &ConductorSpec) -> Option<(TwoMaterial, CurveKind)> {
    let curve = match cd.curve {
        None | Some(CurveSpec::Initial) => CurveKind::Initial,
        Some(CurveSpec::Creep) => CurveKind::Creep,
    };
    if cd.tension_law != TensionLawSpec::TwoMaterial {
        if let Some(k) = cd.curve {
            c.fail(
                "conductor.curve",
                format!("{:?}", format!("{k:?}").to_lowercase()),
                "only with conductor.tension_law = \"two_material\" (the curve of its materials)",
            );
        }
        return None;
    }
    let with_data = || {
        crate::thermal::catalog::catalog()
            .iter()
            .filter(|k| k.stress_strain.is_some())
            .map(|k| format!("\"{}\"", k.name))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let Some(name) = &cd.catalog else {
        c.fail(
            "conductor.tension_law",
            "\"two_material\"",
            &format!(
                "needs conductor.catalog naming a catalogue conductor with stress-strain data (one of {})",
                with_data()
            ),
        );
        return None;
    };
    // The name was found when the catalogue's fields were filled in (scenario::fill_from_catalog), in a
    // user catalogue first: only built-in entries carry stress-strain data.
    let Some(law) = crate::thermal::catalog::find(name).ok().and_then(|k| k.two_material()) else {
        c.fail(
            "conductor.catalog",
            format!("{name:?}"),
            &format!(
                "has no stress-strain data, which conductor.tension_law = \"two_material\" needs (built-in \
                 conductors with them: {})",
                with_data()
            ),
        );
        return None;
    };
    if curve == CurveKind::Creep && (law.outer.creep.is_none() || law.core.is_some_and(|k| k.creep.is_none())) {
        c.fail(
            "conductor.curve",
            "\"creep\"",
            &format!("{name:?} has no creep curve for each of its materials in the catalogue: use \"initial\""),
        );
        return None;
    }
    Some((law, curve))
}
