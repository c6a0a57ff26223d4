//! Conductors beyond the built-in catalogue (`ohl::scenario::thermal_conductor`): a conductor given by its
//! properties is the catalogue's conductor bit for bit when the properties are the catalogue's; a user
//! catalogue file, named relative to the case file, serves thermal cases, `[thermal]` tables and `[conductor]
//! catalog`; bad properties and bad catalogue entries are refused with the file, the field, the value and the
//! allowed range; the inclination is TB 601's and is checked.

use std::path::PathBuf;

use ohl::scenario::{self, thermal};
use ohl::thermal::HeatBalance;
use ohl::thermal::catalog;
use ohl::thermal::steady;
use ohl::thermal::transient::{CurrentSchedule, Transient};

/// Drake's thermal properties as data/conductors.toml gives them, as a TOML table body.
const DRAKE_PROPERTIES: &str = "name = \"Drake by its properties\"\ndiameter_m = 28.14e-3\ncore_diameter_m = 10.4e-3\n\
outer_strand_diameter_m = 4.44e-3\nresistance_low_ohm_per_m = 7.283e-5\ntemperature_low_k = 298.15\n\
resistance_high_ohm_per_m = 8.688e-5\ntemperature_high_k = 348.15\nemissivity = 0.8\nabsorptivity = 0.8\n\
outer_mass_kg_per_m = 1.116\nouter_specific_heat_j_per_kg_k = 897.0\nouter_specific_heat_coefficient_per_k = 3.8e-4\n\
core_mass_kg_per_m = 0.5119\ncore_specific_heat_j_per_kg_k = 481.0\ncore_specific_heat_coefficient_per_k = 1.0e-4\n";

const WEATHER: &str = "[weather]\nair_temperature_k = 303.15\nwind_speed_m_per_s = 0.3\nwind_angle_deg = 30.0\n\
elevation_m = 200.0\n[weather.sun]\nlatitude_deg = 45.0\nday_of_year = 172.0\nsolar_hour = 13.0\n\
line_azimuth_deg = 60.0\n";

fn case_named(standard: &str, extra: &str) -> String {
    format!(
        "standard = \"{standard}\"\nconductor = \"drake\"\n{extra}current_a = [600.0, 1000.0]\n\
         max_temperature_k = [348.15, 373.15]\n{WEATHER}"
    )
}

fn case_by_properties(standard: &str, extra: &str) -> String {
    format!(
        "standard = \"{standard}\"\n{extra}current_a = [600.0, 1000.0]\nmax_temperature_k = [348.15, 373.15]\n\
         {WEATHER}[conductor]\n{DRAKE_PROPERTIES}"
    )
}

/// Everything a thermal case computes, as bits: steady temperatures, ampacities, a transient.
fn outputs(c: &thermal::ThermalCase) -> Vec<u64> {
    let m = c.model().unwrap();
    let mut v = vec![];
    for &i in &c.current_a {
        v.push(steady::temperature(&m, i).unwrap().temperature_k.to_bits());
    }
    for &t in &c.max_temperature_k {
        v.push(steady::ampacity(&m, t).unwrap().current_a.to_bits());
    }
    let sched = CurrentSchedule::step(0.0, 600.0, 1200.0);
    let tr = Transient { model: &m, current: &sched, step_s: 5.0 };
    v.extend(tr.run(0.0, 320.0, 1800.0).iter().map(|s| s.temperature_k.to_bits()));
    v
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl-thermal-conductor-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The built-in catalogue's Drake entry renamed, and a second entry, as a user catalogue.
fn user_catalogue() -> String {
    let text = include_str!("../data/conductors.toml");
    let start = text.find("[[conductor]]\nname = \"ACSR Drake\"").unwrap();
    let end = start + 1 + text[start + 1..].find("[[conductor]]").unwrap();
    let drake = text[start..end]
        .replace("name = \"ACSR Drake\"", "name = \"Site Drake\"")
        .replace(
            "aliases = [\"drake\", \"795 kcmil 26/7\", \"acsr 795 kcmil 26/7\", \"acsr drake 795 kcmil 26/7\"]",
            "aliases = [\"sd\"]",
        )
        .replace("rated_tensile_strength_n = 138.8e3", "rated_tensile_strength_n = 150.0e3");
    assert!(drake.contains("Site Drake") && drake.contains("\"sd\"") && drake.contains("150.0e3"));
    let linnet_start = text.find("[[conductor]]\nname = \"ACSR Linnet\"").unwrap();
    let linnet_end = linnet_start + 1 + text[linnet_start + 1..].find("[[conductor]]").unwrap();
    let other = text[linnet_start..linnet_end]
        .replace("name = \"ACSR Linnet\"", "name = \"Site Linnet\"")
        .replace("aliases = [\"linnet\", \"336.4 kcmil 26/7\", \"acsr 336.4 kcmil 26/7\"]", "aliases = []");
    assert!(other.contains("Site Linnet") && other.contains("aliases = []"));
    format!("{drake}{other}")
}

#[test]
fn a_conductor_given_by_its_properties_is_the_named_one_bit_for_bit() {
    for (standard, extra) in [("ieee738", ""), ("cigre601", ""), ("cigre601", "inclination_deg = 20.0\n")] {
        let named = thermal::parse_case(&case_named(standard, extra), "named.toml").unwrap();
        let given = thermal::parse_case(&case_by_properties(standard, extra), "given.toml").unwrap();
        assert_eq!(given.conductor.label(), "Drake by its properties");
        let (a, b) = (outputs(&named), outputs(&given));
        assert_eq!(a.len(), 4 + 361);
        assert_eq!(a, b, "{standard} {extra}");
    }
    // The same in a scenario: the [thermal] history is the same, sample for sample.
    let base = "[conductor]\ncatalog = \"drake\"\n[geometry]\nleft_support_m = [0.0, 0.0, 30.0]\n\
                right_support_m = [0.0, 300.0, 30.0]\nsegments = 20\nunstretched_length_m = 300.5\n\
                [duration]\nend_time_s = 0.5\n[thermal]\nstandard = \"cigre601\"\ninclination_deg = 5.0\n\
                current_a = [[0.0, 800.0], [0.2, 1200.0]]\nstep_s = 0.05\n";
    let w = "[thermal.weather]\nair_temperature_k = 298.15\nwind_speed_m_per_s = 0.4\nwind_angle_deg = 20.0\n";
    let named = scenario::parse(&format!("{base}conductor = \"ACSR Drake\"\n{w}"), "n.toml").unwrap();
    let given = scenario::parse(&format!("{base}{w}[thermal.conductor]\n{DRAKE_PROPERTIES}"), "g.toml").unwrap();
    let (hn, hg) = (
        scenario::plan(&named, "n.toml").unwrap().thermal.unwrap(),
        scenario::plan(&given, "g.toml").unwrap().thermal.unwrap(),
    );
    assert_eq!(hn.samples, hg.samples);
    assert_eq!(hg.conductor, "Drake by its properties");
    assert!(hn.samples.len() > 10);
}

#[test]
fn a_user_catalogue_relative_to_the_case_file() {
    let dir = tmp("user");
    std::fs::create_dir_all(dir.join("lib")).unwrap();
    std::fs::write(dir.join("lib/site.toml"), user_catalogue()).unwrap();
    let case_path = dir.join("case.toml");
    let file = case_path.display().to_string();
    // A thermal case: the user's "Site Drake" (by an alias) has the built-in Drake's thermal data, so the same
    // results bit for bit; the built-in names stay available next to the user's.
    let with_catalogue = |name: &str| {
        case_named("cigre601", "conductor_catalog = \"lib/site.toml\"\n").replace("\"drake\"", &format!("\"{name}\""))
    };
    let user = thermal::parse_case(&with_catalogue("SD"), &file).unwrap();
    let builtin = thermal::parse_case(&case_named("cigre601", ""), "b.toml").unwrap();
    assert_eq!(user.conductor.label(), "Site Drake");
    assert_eq!(outputs(&user), outputs(&builtin));
    let linnet = thermal::parse_case(&with_catalogue("ACSR Linnet"), &file).unwrap();
    assert_eq!(linnet.conductor.label(), "ACSR Linnet");
    // A name in neither catalogue names both lists.
    let e = thermal::parse_case(&with_catalogue("Condor"), &file).unwrap_err().to_string();
    assert!(e.contains("field `conductor` = \"Condor\"") && e.contains("Site Drake; Site Linnet"), "{e}");
    assert!(e.contains("built-in catalogue (available: ACSR Drake"), "{e}");
    // The path is relative to the case file's folder, not to the working directory.
    let e = thermal::parse_case(&with_catalogue("sd"), "elsewhere/case.toml").unwrap_err().to_string();
    assert!(
        e.contains("field `conductor_catalog` = \"lib/site.toml\"") && e.contains("elsewhere/lib/site.toml"),
        "{e}"
    );

    // A scenario: [thermal] takes the user's conductor, and [conductor] catalog its mechanical data (the
    // user's RTS, 150 kN, not the built-in 138.8 kN).
    let text = "[conductor]\ncatalog = \"Site Drake\"\n[geometry]\nleft_support_m = [0.0, 0.0, 30.0]\n\
                right_support_m = [0.0, 300.0, 30.0]\nsegments = 20\nunstretched_length_m = 300.5\n\
                [duration]\nend_time_s = 0.5\n[thermal]\nconductor = \"site drake\"\n\
                conductor_catalog = \"lib/site.toml\"\ncurrent_a = [[0.0, 800.0]]\n[thermal.weather]\n\
                air_temperature_k = 298.15\nwind_speed_m_per_s = 1.0\n";
    let s = scenario::parse(text, &file).unwrap();
    assert_eq!(s.conductor.rated_tensile_strength_n, Some(150.0e3));
    let drake = catalog::find("drake").unwrap();
    assert_eq!(s.conductor.linear_density_kg_per_m, drake.linear_density_kg_per_m);
    let h = scenario::plan(&s, &file).unwrap().thermal.unwrap();
    assert_eq!(h.conductor, "Site Drake");
    let builtin = scenario::parse(
        &text
            .replace("conductor_catalog = \"lib/site.toml\"\n", "")
            .replace("site drake", "drake")
            .replace("Site Drake", "drake"),
        "b.toml",
    )
    .unwrap();
    assert_eq!(h.samples, scenario::plan(&builtin, "b.toml").unwrap().thermal.unwrap().samples);
}

#[test]
fn bad_properties_and_bad_catalogue_entries_are_refused_with_file_field_value_and_range() {
    // A diameter in millimetres.
    let text = case_by_properties("ieee738", "").replace("diameter_m = 28.14e-3", "diameter_m = 28.14");
    let e = thermal::parse_case(&text, "mm.toml").unwrap_err().to_string();
    assert!(e.contains("mm.toml: field `conductor.diameter_m` = 28.14") && e.contains("[1e-3, 0.2] m"), "{e}");
    // Temperatures in Celsius, and a resistance line that falls with the temperature.
    let text = case_by_properties("ieee738", "")
        .replace("temperature_low_k = 298.15", "temperature_low_k = 25.0")
        .replace("resistance_high_ohm_per_m = 8.688e-5", "resistance_high_ohm_per_m = 6.0e-5");
    let e = thermal::parse_case(&text, "c.toml").unwrap_err().to_string();
    assert!(e.contains("field `conductor.temperature_low_k` = 25") && e.contains("kelvin, not Celsius"), "{e}");
    let text = case_by_properties("ieee738", "")
        .replace("resistance_high_ohm_per_m = 8.688e-5", "resistance_high_ohm_per_m = 6.0e-5");
    let e = thermal::parse_case(&text, "c.toml").unwrap_err().to_string();
    assert!(e.contains("field `conductor.resistance_high_ohm_per_m` = 0.00006") || e.contains("= 6e-5"), "{e}");
    assert!(e.contains("[resistance_low_ohm_per_m, 0.1]"), "{e}");
    // A core without its specific heat; an unknown property (with its line).
    let text = case_by_properties("ieee738", "").replace("core_specific_heat_j_per_kg_k = 481.0\n", "");
    let e = thermal::parse_case(&text, "c.toml").unwrap_err().to_string();
    assert!(e.contains("field `conductor.core_specific_heat_j_per_kg_k` = 0") && e.contains("[100, 5000]"), "{e}");
    let text = case_by_properties("ieee738", "").replace("emissivity = 0.8", "emisivity = 0.8");
    let e = thermal::parse_case(&text, "c.toml").unwrap_err().to_string();
    assert!(e.contains("c.toml") && e.contains("unknown field `emisivity`") && e.contains("line"), "{e}");

    // A bad entry of a user catalogue: the message names the catalogue file and the entry's field.
    let dir = tmp("bad");
    let bad = user_catalogue().replace("resistance_high_ohm_per_m = 2.0308e-4", "resistance_high_ohm_per_m = -1.0");
    assert_ne!(bad, user_catalogue(), "Linnet's R(75 C) is 2.0308e-4 ohm/m in data/conductors.toml");
    std::fs::write(dir.join("site.toml"), bad).unwrap();
    let file = dir.join("case.toml").display().to_string();
    let text = case_named("ieee738", "conductor_catalog = \"site.toml\"\n");
    let e = thermal::parse_case(&text, &file).unwrap_err().to_string();
    assert!(e.contains("site.toml (conductor_catalog of") && e.contains("case.toml)"), "{e}");
    assert!(e.contains("field `conductor[1].resistance_high_ohm_per_m` = -1"), "{e}");
}

#[test]
fn the_inclination_is_tb601s_and_within_its_range() {
    // In still air natural convection is all the convection: the inclined span's is eq. (24)'s factor times
    // the level one's (stranded: 1 - 1.76e-6 * 30^2.5 = 0.99132), and the span is hotter.
    let still = |extra: &str| {
        let text = case_named("cigre601", extra).replace("wind_speed_m_per_s = 0.3", "wind_speed_m_per_s = 0.0");
        thermal::parse_case(&text, "i.toml").unwrap().model().unwrap()
    };
    let (mi, ml) = (still("inclination_deg = 30.0\n"), still(""));
    let t = 348.15;
    let ratio = mi.terms(t, 0.0).convection_w_per_m / ml.terms(t, 0.0).convection_w_per_m;
    assert!((ratio - (1.0 - 1.76e-6 * 30f64.powf(2.5))).abs() < 1e-12, "{ratio}");
    assert!((ratio - 0.99132).abs() < 1e-5, "{ratio}");
    let (ti, tl) = (
        steady::temperature(&mi, 1000.0).unwrap().temperature_k,
        steady::temperature(&ml, 1000.0).unwrap().temperature_k,
    );
    assert!(ti > tl, "{ti} {tl}");
    let e = thermal::parse_case(&case_named("ieee738", "inclination_deg = 30.0\n"), "i.toml").unwrap_err().to_string();
    assert!(e.contains("field `inclination_deg` = 30") && e.contains("CIGRE TB 601 only"), "{e}");
    let e = thermal::parse_case(&case_named("cigre601", "inclination_deg = 85.0\n"), "i.toml").unwrap_err().to_string();
    assert!(e.contains("field `inclination_deg` = 85") && e.contains("[0, 80] deg for a stranded conductor"), "{e}");
}
