//! Physics of the wire: the discrete, absolutely flexible wire of section 1, its state in
//! structure-of-arrays form, its constitutive law and the distributed loads on it.
//!
//! Grid (section 3): nodes `i = 0..=N` at Lagrangian coordinates `s_i` carry position `r_i` and
//! velocity `v_i`; segments `i+1/2` (stored at index `i = 0..N`) carry the stress-free length
//! `l0_{i+1/2}`, the mass, and (computed each step) strain, strain rate and tension. A node's mass is half
//! the mass of each adjacent segment (a lumped-mass form of `dm = rho0 ds0`, section 1).
//!
//! Coordinates as in the paper: `x1` horizontal across the line (the wind direction), `x2` along the
//! span, `x3` vertical up; gravity acts along `-x3`. Plane problems are this same 3D wire with unused
//! components zero.

pub mod insulator;
pub mod material;
pub mod section;

pub use insulator::{Crossarm, Insulator};
pub use material::Material;

use crate::element::tension;

/// Default reference temperature [K]: 268.15 K = -5 C, the ambient temperature of section 5.4.
pub const REFERENCE_TEMPERATURE_K: f64 = 268.15;

/// Properties of a conductor: the material a uniform wire is built from ([`Wire::new`]); each segment
/// keeps its own copy of them, so a line may join conductors of different kinds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conductor {
    /// axial stiffness `EA` [N]
    pub axial_stiffness_n: f64,
    /// Kelvin-Voigt internal friction `eta` [N s], eq. (3.4)
    pub internal_friction_n_s: f64,
    /// constitutive law: tension-only (default) or linear
    pub law: tension::LawKind,
}

/// How a node is held.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Constraint {
    /// the node moves under the forces on it
    Free,
    /// the node is held at its position (a dead-end support); the force the wire applies to it is the
    /// support load ([`crate::scheme::Explicit::support_forces`])
    Fixed,
}

/// The discrete line: node and segment arrays, each a contiguous `Vec<f64>` per component. Every
/// segment carries its own material (axial stiffness, internal friction, mass, stress-free length), and
/// every node its own [`Constraint`]; a single span is a line whose two end nodes are fixed.
#[derive(Clone, Debug)]
pub struct Wire {
    /// constitutive law of every segment (chosen once per run: the kernel is specialised on it)
    pub law: tension::LawKind,
    /// how each node is held, length `N + 1` (changed with [`Wire::set_constraint`])
    constraint: Vec<Constraint>,
    /// the fixed nodes, in node order (kept with `constraint`)
    fixed: Vec<usize>,
    /// segment axial stiffness `EA_{i+1/2}` [N], length `N`
    pub axial_stiffness_n: Vec<f64>,
    /// segment Kelvin-Voigt internal friction `eta_{i+1/2}` [N s], eq. (3.4), length `N`
    pub internal_friction_n_s: Vec<f64>,
    /// node positions `x1, x2, x3` [m], each of length `N + 1`
    pub x: [Vec<f64>; 3],
    /// node velocities `v1, v2, v3` [m/s] at the last half step `n - 1/2`, each of length `N + 1`
    pub v: [Vec<f64>; 3],
    /// lumped node mass `m_i` [kg]
    pub mass: Vec<f64>,
    /// `1 / m_i` [1/kg]
    pub inv_mass: Vec<f64>,
    /// 1.0 for a free node, 0.0 for a fixed one [-] (the kernel's form of the constraints; change them
    /// with [`Wire::set_constraint`])
    pub free: Vec<f64>,
    /// segment stress-free length `l0_{i+1/2}` [m], length `N` (thermal strain scales it)
    pub rest_length: Vec<f64>,
    /// segment unstretched length at the reference temperature `L_{i+1/2}` [m], length `N`
    pub reference_length: Vec<f64>,
    /// segment mass `rho0 L` [kg], length `N` (ice changes it)
    pub segment_mass: Vec<f64>,
    /// 1.0 for an intact segment, 0.0 for a broken one [-], length `N` (the break (3.5))
    pub intact: Vec<f64>,
    /// the diameter the wind acts on over the conductor's `k = (d + 2 t) / d` [-], length `N`: 1.0 bare,
    /// radial ice `t` enlarges it ([`Wire::set_radial_ice`]; the aerodynamic law (2.5)-(2.6) scales by it)
    pub wind_diameter_factor: Vec<f64>,
    /// mass of the radial ice shell of each segment per unit reference length `rho_ice pi t (d + t)`
    /// [kg/m], length `N` (0 bare; ice given in kg/m is not in it: it enlarges no diameter)
    pub radial_ice_kg_per_m: Vec<f64>,
    /// 1.0 while distributed loads (wind, uniform load) act on the node, 0.0 once it has touched the
    /// ground (section 4.4, assumption b) [-], length `N + 1`
    pub exposed: Vec<f64>,
    /// segment temperature `u_{i+1/2}` [K], length `N`
    pub temperature_k: Vec<f64>,
    /// temperature at which `reference_length` is stress-free [K]
    pub reference_temperature_k: f64,
    /// linear thermal expansion coefficient `alpha_t` [1/K], eq. (5.5)
    pub thermal_expansion_per_k: f64,
    /// point mass lumped at each node besides the conductor `m_p` [kg] (an insulator string at its clamp),
    /// length `N + 1`; call [`Wire::update_node_masses`] after changing it
    pub point_mass_kg: Vec<f64>,
    /// suspension insulator strings, each holding a node of the line ([`insulator`])
    pub insulators: Vec<Insulator>,
    /// weights of the mass-weighted smoothing (3.3) at each node: `[m_{i-1/2} / m_i, m_{i+1/2} / m_i]`,
    /// the masses of the segments left and right of node `i` over the node's lumped mass [-] (0 where
    /// there is no segment); kept by [`Wire::update_node_masses`] ([`crate::scheme::smoothing`])
    pub smoothing_weight: [Vec<f64>; 2],
    /// whether every free node has both weights equal to 1 (a uniform wire, no point masses), where the
    /// weighted smoothing is exactly the paper's (3.3) and the kernel takes the unweighted path
    pub uniform_smoothing: bool,
    /// the two-material law and each segment's history when `law` is [`tension::LawKind::TwoMaterial`]
    /// ([`material`]; set with [`Wire::set_two_material`]), `None` otherwise
    pub material: Option<Material>,
}

impl Wire {
    /// A wire through the given node positions, at rest, with the given segment stress-free lengths and
    /// linear density `rho0` [kg/m] per unit stress-free length; both end nodes are fixed supports.
    ///
    /// Panics on inconsistent array lengths (internal misuse); physical input is validated upstream.
    pub fn new(conductor: Conductor, x: [Vec<f64>; 3], rest_length: Vec<f64>, linear_density_kg_per_m: f64) -> Self {
        let n_nodes = x[0].len();
        assert!(n_nodes >= 3, "a wire needs at least two segments");
        assert!(x.iter().all(|c| c.len() == n_nodes) && rest_length.len() == n_nodes - 1);
        let segment_mass: Vec<f64> = rest_length.iter().map(|l| l * linear_density_kg_per_m).collect();
        let n = n_nodes - 1;
        let mut constraint = vec![Constraint::Free; n_nodes];
        constraint[0] = Constraint::Fixed;
        constraint[n] = Constraint::Fixed;
        let mut wire = Wire {
            law: conductor.law,
            free: constraint.iter().map(|c| if *c == Constraint::Free { 1.0 } else { 0.0 }).collect(),
            fixed: vec![0, n],
            constraint,
            axial_stiffness_n: vec![conductor.axial_stiffness_n; n],
            internal_friction_n_s: vec![conductor.internal_friction_n_s; n],
            v: [vec![0.0; n_nodes], vec![0.0; n_nodes], vec![0.0; n_nodes]],
            x,
            mass: vec![0.0; n_nodes],
            inv_mass: vec![0.0; n_nodes],
            reference_length: rest_length.clone(),
            rest_length,
            segment_mass,
            intact: vec![1.0; n_nodes - 1],
            wind_diameter_factor: vec![1.0; n_nodes - 1],
            radial_ice_kg_per_m: vec![0.0; n_nodes - 1],
            exposed: vec![1.0; n_nodes],
            temperature_k: vec![REFERENCE_TEMPERATURE_K; n_nodes - 1],
            reference_temperature_k: REFERENCE_TEMPERATURE_K,
            thermal_expansion_per_k: 0.0,
            point_mass_kg: vec![0.0; n_nodes],
            insulators: Vec::new(),
            smoothing_weight: [vec![0.0; n_nodes], vec![0.0; n_nodes]],
            uniform_smoothing: true,
            material: None,
        };
        wire.update_node_masses();
        wire
    }

    /// Number of segments `N`.
    pub fn segments(&self) -> usize {
        self.rest_length.len()
    }

    /// Number of nodes `N + 1`.
    pub fn nodes(&self) -> usize {
        self.x[0].len()
    }

    /// Recompute the lumped node masses from the segment masses (after ice is added or dropped) and the
    /// point masses, and the smoothing weights that follow from them.
    pub fn update_node_masses(&mut self) {
        let n = self.segments();
        for i in 0..=n {
            let left = if i > 0 { self.segment_mass[i - 1] } else { 0.0 };
            let right = if i < n { self.segment_mass[i] } else { 0.0 };
            self.mass[i] = 0.5 * (left + right) + self.point_mass_kg[i];
            self.inv_mass[i] = 1.0 / self.mass[i];
            self.smoothing_weight[0][i] = left / self.mass[i];
            self.smoothing_weight[1][i] = right / self.mass[i];
        }
        self.update_uniform_smoothing();
    }

    /// Whether the weighted smoothing reduces to the paper's on every free node (both weights exactly 1;
    /// a free end node, with half a segment's mass, has weight 2 and is not uniform).
    fn update_uniform_smoothing(&mut self) {
        let n = self.segments();
        let [left, right] = &self.smoothing_weight;
        self.uniform_smoothing =
            (0..=n).all(|i| self.free[i] <= 0.0 || ((i == 0 || left[i] == 1.0) && (i == n || right[i] == 1.0)));
    }

    /// Indices of the fixed nodes (the supports), in node order.
    pub fn fixed_nodes(&self) -> &[usize] {
        &self.fixed
    }

    /// The supports in node order: each fixed node with its position, and each suspension string's clamp
    /// node with the string's pivot [m] (the point the support force acts on).
    pub fn supports(&self) -> Vec<(usize, [f64; 3])> {
        let mut out: Vec<(usize, [f64; 3])> = self.fixed.iter().map(|&i| (i, self.position(i))).collect();
        out.extend(self.insulators.iter().map(|s| (s.node, s.pivot_m)));
        out.sort_by_key(|&(i, _)| i);
        out
    }

    /// Whether node `i` is held in place: fixed, or hanging from an intact suspension string.
    pub fn is_held(&self, i: usize) -> bool {
        self.free[i] <= 0.0 || self.insulators.iter().any(|s| s.node == i && s.intact)
    }

    /// How node `i` is held.
    pub fn constraint(&self, i: usize) -> Constraint {
        self.constraint[i]
    }

    /// Hold node `i` fixed or let it move.
    pub fn set_constraint(&mut self, i: usize, c: Constraint) {
        self.constraint[i] = c;
        self.free[i] = if c == Constraint::Free { 1.0 } else { 0.0 };
        self.fixed = (0..self.nodes()).filter(|&j| self.constraint[j] == Constraint::Fixed).collect();
        self.update_uniform_smoothing();
    }

    /// Position of node `i` [m].
    pub fn position(&self, i: usize) -> [f64; 3] {
        [self.x[0][i], self.x[1][i], self.x[2][i]]
    }

    /// The constants of segment `j` as the segment element takes them ([`crate::element::segment`]).
    pub fn segment_props(&self, j: usize) -> crate::element::segment::SegmentProps {
        crate::element::segment::SegmentProps {
            axial_stiffness_n: self.axial_stiffness_n[j],
            internal_friction_n_s: self.internal_friction_n_s[j],
            rest_length_m: self.rest_length[j],
            reference_length_m: self.reference_length[j],
            intact: self.intact[j],
            wind_diameter_factor: self.wind_diameter_factor[j],
        }
    }

    /// Velocity of node `i` [m/s] (the half-step `v^{n-1/2}` between steps).
    pub fn velocity(&self, i: usize) -> [f64; 3] {
        [self.v[0][i], self.v[1][i], self.v[2][i]]
    }

    /// Strain `e = |r_{j+1} - r_j| / l0 - 1` of segment `j` [-], as the segment element forms it
    /// ([`crate::element::segment::stretch`]).
    pub fn strain(&self, j: usize) -> f64 {
        let zero = [0.0; 3];
        crate::element::segment::stretch(self.position(j), self.position(j + 1), zero, zero, self.rest_length[j]).e
    }

    /// Total stress-free length `sum l0` [m].
    pub fn total_rest_length(&self) -> f64 {
        self.rest_length.iter().sum()
    }

    /// Total mass of the conductor [kg] (point masses not included).
    pub fn total_mass(&self) -> f64 {
        self.segment_mass.iter().sum()
    }

    /// Hang node `node` from a suspension insulator string (its mass lumped at the node).
    pub fn add_insulator(&mut self, ins: Insulator) {
        self.point_mass_kg[ins.node] += ins.mass_kg;
        self.insulators.push(ins);
        self.update_node_masses();
    }

    /// The point at the middle of the span in the Lagrangian coordinate, `s = S/2` [m]: node `N/2` for
    /// even `N`, the mean of the two middle nodes for odd `N` (docs/paper_notes.md, "Mid-span").
    pub fn midspan(&self) -> [f64; 3] {
        let n = self.segments();
        let (a, b) = (n / 2, n.div_ceil(2));
        let (pa, pb) = (self.position(a), self.position(b));
        [0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])]
    }

    /// Break segment `j` (3.5): its tension and loads vanish and its end nodes become free ends whose
    /// ghost nodes copy their velocity; each part continues as a free-ended wire.
    pub fn break_segment(&mut self, j: usize) {
        self.intact[j] = 0.0;
    }

    /// Add `delta_kg_per_m` [kg/m] of linear density (ice; negative to drop it) on segments `range`,
    /// per unit reference length, and update the node masses. A change that would leave some segment
    /// mass non-positive (or not finite) is refused: the wire is left unchanged and `false` returned
    /// (scenario validation refuses such events up front, [`crate::scenario::validate`]).
    #[must_use = "a refused change leaves the wire unchanged"]
    pub fn add_linear_density(&mut self, range: std::ops::Range<usize>, delta_kg_per_m: f64) -> bool {
        if range.end > self.segments() || range.start > range.end {
            return false;
        }
        let after = |m: f64, l: f64| m + delta_kg_per_m * l;
        let ok = range.clone().all(|j| {
            let m = after(self.segment_mass[j], self.reference_length[j]);
            m.is_finite() && m > 0.0
        });
        if !ok {
            return false;
        }
        for j in range {
            self.segment_mass[j] = after(self.segment_mass[j], self.reference_length[j]);
        }
        self.update_node_masses();
        true
    }

    /// Set the radial ice shell of segments `range`: `kg_per_m` [kg/m] per unit reference length (its mass
    /// `rho_ice pi t (d + t)`) and the wind diameter factor `(d + 2 t) / d` [-]. The shell replaces the one
    /// the segments had (the segment mass changes by the difference; ice given in kg/m stays). A shell
    /// that is negative, not finite, or a factor below 1 is refused: the wire is left unchanged and `false`
    /// returned (validation refuses such events up front).
    #[must_use = "a refused change leaves the wire unchanged"]
    pub fn set_radial_ice(&mut self, range: std::ops::Range<usize>, kg_per_m: f64, diameter_factor: f64) -> bool {
        if range.end > self.segments()
            || range.start > range.end
            || !(kg_per_m.is_finite() && kg_per_m >= 0.0)
            || !(diameter_factor.is_finite() && diameter_factor >= 1.0)
        {
            return false;
        }
        for j in range {
            let m = self.segment_mass[j] + (kg_per_m - self.radial_ice_kg_per_m[j]) * self.reference_length[j];
            // The shell's own mass is what leaves, so the mass stays positive; the bound only guards it.
            self.segment_mass[j] = m.max(f64::MIN_POSITIVE);
            self.radial_ice_kg_per_m[j] = kg_per_m;
            self.wind_diameter_factor[j] = diameter_factor;
        }
        self.update_node_masses();
        true
    }

    /// Let every segment follow the two-material law `law` ([`material`]), virgin on the curve `curve`:
    /// the law becomes [`tension::LawKind::TwoMaterial`], the reference lengths `L` are read as the
    /// conductor's lengths at the law's reference temperature, the stress-free lengths stay at `L` (the
    /// law takes each segment's temperature), and the axial stiffness `EA` of every segment becomes the
    /// law's stiffness bound [`Material::max_stiffness`] (the time step's and the static scales' `EA`).
    pub fn set_two_material(&mut self, law: crate::conductor::TwoMaterial, curve: crate::conductor::CurveKind) {
        let m = Material::virgin(law, curve, self.segments());
        self.axial_stiffness_n.fill(m.max_stiffness());
        self.law = tension::LawKind::TwoMaterial;
        self.material = Some(m);
        self.update_rest_lengths();
    }

    /// Moves each two-material segment's history up to its present strain (a static "stretch": after a
    /// static solve under a heavy load, the conductor keeps its permanent set). Nothing for other laws.
    pub fn load_history(&mut self) {
        let strains: Vec<f64> = (0..self.segments()).map(|j| self.strain(j)).collect();
        if let Some(m) = self.material.as_mut() {
            for (j, &e) in strains.iter().enumerate() {
                if self.intact[j] > 0.0 {
                    m.load(j, e, self.temperature_k[j]);
                }
            }
        }
    }

    /// Set the temperature [K] of segments `range` and rescale their stress-free lengths by thermal
    /// strain: `l0 = L (1 + alpha_t (u - u_ref))`, eqs. (5.5)-(5.6) (a two-material segment keeps `l0 = L`:
    /// its law takes the temperature, [`material`]).
    pub fn set_temperature(&mut self, range: std::ops::Range<usize>, temperature_k: f64) {
        for j in range {
            self.temperature_k[j] = temperature_k;
        }
        self.update_rest_lengths();
    }

    /// Set the temperature `temperature_k` [K] on every segment and rescale the stress-free lengths:
    /// [`Wire::update_rest_lengths`] after filling `temperature_k`, bit for bit. The thermal factor
    /// `1 + alpha_t (u - u_ref)` is the same for every segment, so it is formed once (the same operations
    /// on the same operands give the same bits) and each length is one multiplication `L * factor`
    /// (IEEE multiplication is commutative: `factor * L` has the bits of `L * factor`).
    #[inline(always)]
    pub fn set_uniform_temperature(&mut self, temperature_k: f64) {
        self.temperature_k.fill(temperature_k);
        if self.material.is_some() {
            self.rest_length.copy_from_slice(&self.reference_length);
            return;
        }
        let factor = thermal_factor(self.thermal_expansion_per_k, temperature_k, self.reference_temperature_k);
        for (l0, &l) in self.rest_length.iter_mut().zip(&self.reference_length) {
            *l0 = l * factor;
        }
    }

    /// Recompute every stress-free length from `temperature_k` (after a heat-equation step wrote it).
    pub fn update_rest_lengths(&mut self) {
        if self.material.is_some() {
            self.rest_length.copy_from_slice(&self.reference_length);
            return;
        }
        let (a, u0) = (self.thermal_expansion_per_k, self.reference_temperature_k);
        // Zipped (no index checks: the compiler may take two segments at once, each the same operations).
        for ((l0, &l), &u) in self.rest_length.iter_mut().zip(&self.reference_length).zip(&self.temperature_k) {
            *l0 = l * thermal_factor(a, u, u0);
        }
    }
}

/// The thermal factor of (5.5), `L0 = L (1 + alpha_t (u - u_ref))`: `1 + alpha (u - u_ref)` [-] for the
/// expansion coefficient `alpha` [1/K] at the temperature `u` [K] over the reference `u_ref` [K] (one
/// definition: the same operations, the same bits, wherever a stress-free length is scaled).
#[inline(always)]
pub fn thermal_factor(alpha: f64, u: f64, u_ref: f64) -> f64 {
    1.0 + alpha * (u - u_ref)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A straight wire of `n` segments `ds` [m] apart along `x2`, stress-free lengths `ds + 1e-3 sin(w j)`
    /// [m] (none equal), `mass` [kg/m] and thermal expansion `alpha` [1/K]: the rest-length tests' wire.
    fn thermal_wire(n: usize, ds: f64, w: f64, mass: f64, alpha: f64) -> Wire {
        let conductor =
            Conductor { axial_stiffness_n: 1.0, internal_friction_n_s: 0.0, law: tension::LawKind::TensionOnly };
        let x = [vec![0.0; n + 1], (0..=n).map(|i| i as f64 * ds).collect(), vec![0.0; n + 1]];
        let mut wire = Wire::new(conductor, x, (0..n).map(|j| ds + 1e-3 * (w * j as f64).sin()).collect(), mass);
        wire.thermal_expansion_per_k = alpha;
        wire
    }

    /// The zipped loop of `update_rest_lengths` gives the bits of the indexed formula
    /// `L0_j = L_j (1 + a (u_j - u_0))` over pseudo-random temperatures and lengths.
    #[test]
    fn rest_lengths_are_the_indexed_formula() {
        let n = 37;
        let mut w = thermal_wire(n, 8.0, 1.0, 1.0, 1.93e-5);
        for j in 0..n {
            w.temperature_k[j] = 288.15 + 90.0 * (0.7 * j as f64).cos();
        }
        w.update_rest_lengths();
        let (a, u0) = (w.thermal_expansion_per_k, w.reference_temperature_k);
        for j in 0..n {
            let want = w.reference_length[j] * (1.0 + a * (w.temperature_k[j] - u0));
            assert_eq!(w.rest_length[j].to_bits(), want.to_bits(), "segment {j}");
        }
        assert!(w.rest_length[0] != w.reference_length[0]);
    }

    /// `set_uniform_temperature` (the thermal factor formed once) gives the bits of filling the
    /// temperatures and `update_rest_lengths` (the factor formed per segment), over many temperatures.
    #[test]
    fn a_uniform_temperature_is_update_rest_lengths_bit_for_bit() {
        let n = 41;
        let mut a = thermal_wire(n, 7.5, 1.3, 1.6, 1.89e-5);
        let mut b = a.clone();
        for k in 0..500 {
            let temp = 250.0 + 0.37 * k as f64 + 1e-9 * (k as f64).cos();
            a.set_uniform_temperature(temp);
            b.temperature_k.fill(temp);
            b.update_rest_lengths();
            for j in 0..n {
                assert_eq!(a.temperature_k[j].to_bits(), b.temperature_k[j].to_bits());
                assert_eq!(a.rest_length[j].to_bits(), b.rest_length[j].to_bits(), "segment {j} at {temp} K");
            }
        }
    }

    #[test]
    fn a_radial_shell_replaces_the_previous_one_and_sheds_to_the_mass_without_it() {
        // 20 segments of 8 m at 1 kg/m, 0.5 kg/m of kg/m ice on all, then shells on 5..15.
        let conductor =
            Conductor { axial_stiffness_n: 1.0, internal_friction_n_s: 0.0, law: tension::LawKind::TensionOnly };
        let n = 20;
        let x = [vec![0.0; n + 1], (0..=n).map(|i| i as f64 * 8.0).collect(), vec![0.0; n + 1]];
        let mut w = Wire::new(conductor, x, vec![8.0; n], 1.0);
        assert!(w.add_linear_density(0..n, 0.5));
        // Masses are exact binary fractions here (1.5, 2.25, 1.75 kg/m on 8 m), so equality is exact.
        assert!(w.set_radial_ice(5..15, 0.75, 3.0));
        assert_eq!((w.segment_mass[4], w.segment_mass[5], w.segment_mass[14]), (12.0, 18.0, 18.0));
        assert_eq!((w.wind_diameter_factor[4], w.wind_diameter_factor[5]), (1.0, 3.0));
        // A new shell replaces the old (not added to it); the kg/m ice stays.
        assert!(w.set_radial_ice(10..15, 0.25, 2.0));
        assert_eq!((w.segment_mass[9], w.segment_mass[10]), (18.0, 14.0));
        assert_eq!((w.wind_diameter_factor[9], w.wind_diameter_factor[10]), (3.0, 2.0));
        // Shedding (t = 0: no mass, factor 1) leaves the wire with its kg/m ice only.
        assert!(w.set_radial_ice(0..n, 0.0, 1.0));
        assert!(w.segment_mass.iter().all(|&m| m == 12.0));
        assert!(w.wind_diameter_factor.iter().all(|&k| k == 1.0));
        assert_eq!(w.mass[10], 12.0);
        // Invalid shells are refused and change nothing.
        let before = w.segment_mass.clone();
        assert!(!w.set_radial_ice(0..n, -0.1, 1.0));
        assert!(!w.set_radial_ice(0..n, 0.1, 0.5));
        assert!(!w.set_radial_ice(0..n + 1, 0.1, 1.5));
        assert!(!w.set_radial_ice(0..n, f64::NAN, 1.5));
        assert_eq!(w.segment_mass, before);
    }
}
