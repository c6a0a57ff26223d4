//! `[conductor] catalog = "NAME"` takes the fields the table does not give from the conductor catalogue
//! (`data/conductors.toml`): the built wire carries the catalogue's linear density, axial stiffness and
//! thermal expansion exactly, a field given in the file wins over the catalogue's, and an unknown name is
//! refused with the field and the names available.

use ohl::scenario;
use ohl::thermal::catalog;

fn scenario_with(conductor: &str) -> String {
    format!(
        "[conductor]\n{conductor}\n\n[geometry]\nleft_support_m = [0.0, 0.0, 30.0]\nright_support_m = [0.0, 200.0, 30.0]\n\
         segments = 20\nunstretched_length_m = 200.5\n\n[duration]\nend_time_s = 0.1\n"
    )
}

#[test]
fn catalogue_fills_the_conductor_and_given_fields_win() {
    let k = catalog::find("ACSR Linnet").unwrap();
    let s = scenario::parse(&scenario_with("catalog = \"linnet\""), "t.toml").unwrap();
    let plan = scenario::plan(&s, "t.toml").unwrap();
    let w = plan.solver.wire();
    // Mass is density times unstretched length, exactly as the wire lumps it.
    assert!((w.total_mass() - k.linear_density_kg_per_m * 200.5).abs() < 1e-12 * w.total_mass());
    assert_eq!(w.axial_stiffness_n[0], k.axial_stiffness_n);
    assert_eq!(w.thermal_expansion_per_k, k.thermal_expansion_per_k);
    assert_eq!(s.conductor.diameter_m, Some(k.diameter_m));
    assert_eq!(s.conductor.rated_tensile_strength_n, Some(k.rated_tensile_strength_n));
    // A field given in the file wins.
    let s = scenario::parse(&scenario_with("catalog = \"linnet\"\naxial_stiffness_n = 1.0e7"), "t.toml").unwrap();
    assert_eq!(s.conductor.axial_stiffness_n, Some(1.0e7));
    // With a Young's modulus the catalogue's EA is not added (it would be given twice).
    let s = scenario::parse(&scenario_with("catalog = \"linnet\"\nyoungs_modulus_pa = 7.0e10"), "t.toml").unwrap();
    assert_eq!(s.conductor.axial_stiffness_n, None);
}

#[test]
fn unknown_catalogue_name_is_refused_with_the_field() {
    let e = scenario::parse(&scenario_with("catalog = \"ACSR Condor\""), "t.toml").unwrap_err().to_string();
    assert!(e.contains("field `conductor.catalog` = \"ACSR Condor\"") && e.contains("ACSR Drake"), "{e}");
}
