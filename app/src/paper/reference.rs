//! Independent references for a check, computed with [`ohl::exact`] from the scenario's data and the
//! wire's state at the extraction time (its mass, stress-free length and temperature then), never from
//! the run's results. See [`crate::paper::spec::ReferenceKind`].

use crate::paper::spec::{ExtractKind, ExtractSpec, ReferenceKind};
use ohl::exact::{ElasticArc, ElasticCatenary, paper_arc_deflection_m, paper_parabolic_sag_m};
use ohl::run::Probe;
use ohl::scenario::Plan;
use ohl::scheme::WindLoad;

/// The uniform normal wind pressure `p` [N/m] times the multiplier at the time, and its direction.
fn pressure(plan: &Plan, p: &Probe) -> Option<(f64, [f64; 3])> {
    match plan.solver.loads().wind {
        Some(WindLoad::UniformNormal(u)) => Some((u.pressure_n_per_m * p.wind_scale, u.direction)),
        _ => None,
    }
}

/// What a check extracts, as a quantity of a static solution.
enum Quantity {
    Displacement(usize),
    MaxTension,
    SupportTension,
    Other,
}

fn quantity(x: &ExtractSpec) -> Quantity {
    let k = x.component.map_or(2, |c| c.index());
    match x.kind {
        ExtractKind::Midspan => Quantity::Displacement(k),
        ExtractKind::MaxTension => Quantity::MaxTension,
        ExtractKind::SupportTension => Quantity::SupportTension,
        _ => Quantity::Other,
    }
}

/// The reference value [SI], or `None` where the reference does not define the extracted quantity.
pub fn reference(kind: ReferenceKind, plan: &Plan, x: &ExtractSpec, p: &Probe) -> Option<f64> {
    let w = &plan.solver.wire();
    let ea = w.axial_stiffness_n[0];
    let (a, b) = (plan.left_support_m, plan.right_support_m);
    let g = plan.solver.loads().gravity_m_per_s2;
    let l0 = p.rest_length_m;
    let weight = g * p.mass_kg / l0;
    let q = quantity(x);
    match kind {
        ReferenceKind::ExactArc | ReferenceKind::PaperArc => {
            let Quantity::Displacement(k) = q else { return None };
            let (pr, dir) = pressure(plan, p)?;
            let f = if kind == ReferenceKind::ExactArc {
                ElasticArc::solve(plan.chord_m, l0, pr, ea).ok()?.max_deflection_m()
            } else {
                paper_arc_deflection_m(plan.chord_m, pr, ea).ok()?
            };
            Some(f * dir[k])
        }
        ReferenceKind::ExactCatenary | ReferenceKind::ExactCatenaryWithWind => {
            let mut load = [0.0, 0.0, -weight];
            if kind == ReferenceKind::ExactCatenaryWithWind {
                let (pr, dir) = pressure(plan, p)?;
                for k in 0..3 {
                    load[k] += pr * dir[k];
                }
            }
            let c = ElasticCatenary::solve(a, b, l0, load, ea).ok()?;
            match q {
                Quantity::Displacement(k) => Some(c.midspan_displacement_m()[k]),
                Quantity::MaxTension => Some(c.max_tension_n()),
                Quantity::SupportTension => Some(c.tension_n(0.0)),
                Quantity::Other => None,
            }
        }
        ReferenceKind::PaperParabola => {
            let Quantity::Displacement(2) = q else { return None };
            Some(-paper_parabolic_sag_m(plan.chord_m, weight, ea).ok()?)
        }
        ReferenceKind::ThermalStrain | ReferenceKind::ThermalForce => {
            let eps = w.thermal_expansion_per_k * (p.mean_temperature_k - w.reference_temperature_k);
            Some(if kind == ReferenceKind::ThermalForce { ea * eps } else { eps })
        }
    }
}
