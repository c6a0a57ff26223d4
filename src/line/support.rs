//! Supports shared by several attachments: a tower top, a crossarm, a portal beam, carrying every phase
//! and earth wire that hangs on it.
//!
//! A support is a point `p` (its reference point) that is either rigid (fixed) or an elastic body that
//! translates horizontally on springs along and across the line, rigid vertically (the tower's bending
//! flexibility at its top, which lowers broken-wire peaks):
//!
//! ```text
//! M a = -k_l ((p - p0) . e_l) e_l - k_t ((p - p0) . e_t) e_t - c_d u + sum_attachments F,   a . e3 = 0,
//! ```
//!
//! with `e_l` the horizontal unit vector along the line, `e_t = e3 x e_l`, `M` [kg] the mass that moves
//! with the top, `c_d` [N s/m] a viscous damping, `u` the velocity at the previous half step, and `F` the
//! forces of its attachments ([`super::Link`]) and of the conductor nodes held on it ([`super::DeadEnd`],
//! rigid supports only). The explicit integrator advances it with the conductors' leapfrog
//! ([`crate::scheme::line`]); the static solver will add its two horizontal displacements as unknowns
//! (the degree-of-freedom map of a support).
//!
//! Angles: `e_t = e3 x e_l` is to the LEFT of the direction of the line (for a line along +x2, `e_t` is
//! -x1), the sense in which the section outputs measure `swing_across_deg`.

/// The elastic part of a support.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticSupport {
    /// horizontal unit vector along the line `e_l` [-]
    pub along: [f64; 3],
    /// spring along the line `k_l` [N/m]
    pub along_n_per_m: f64,
    /// spring across the line `k_t` [N/m]
    pub across_n_per_m: f64,
    /// mass moving with the support `M` [kg]
    pub mass_kg: f64,
    /// viscous damping `c_d` [N s/m]
    pub damping_n_s_per_m: f64,
}

impl ElasticSupport {
    /// Transverse unit vector `e_t = e3 x e_l` [-].
    pub fn across(&self) -> [f64; 3] {
        [-self.along[1], self.along[0], 0.0]
    }

    /// Spring and damping force [N] at displacement `d = p - p0` [m] and velocity `u` [m/s]; no vertical
    /// component (the support is rigid vertically).
    pub fn spring_force(&self, d: [f64; 3], u: [f64; 3]) -> [f64; 3] {
        let (el, et) = (self.along, self.across());
        let (dl, dt) = (dot(d, el), dot(d, et));
        std::array::from_fn(|k| {
            if k == 2 {
                0.0
            } else {
                -self.along_n_per_m * dl * el[k] - self.across_n_per_m * dt * et[k] - self.damping_n_s_per_m * u[k]
            }
        })
    }

    /// Elastic energy of the springs at displacement `d` [m] [J].
    pub fn spring_energy_j(&self, d: [f64; 3]) -> f64 {
        let (dl, dt) = (dot(d, self.along), dot(d, self.across()));
        0.5 * (self.along_n_per_m * dl * dl + self.across_n_per_m * dt * dt)
    }
}

/// A support of the line.
#[derive(Clone, Debug, PartialEq)]
pub struct Support {
    /// name (for outputs), e.g. `"tower 2"`
    pub name: String,
    /// position of the reference point at rest `p0` [m]
    pub position_m: [f64; 3],
    /// `None` for a rigid support
    pub elastic: Option<ElasticSupport>,
}

impl Support {
    /// A rigid support at `position_m` [m].
    pub fn rigid(name: impl Into<String>, position_m: [f64; 3]) -> Self {
        Support { name: name.into(), position_m, elastic: None }
    }
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
