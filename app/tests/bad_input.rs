//! Issue test 4: invalid scenarios are refused before anything runs, with a message that names the
//! file, the field, the value and what is allowed, and exit code 2; never a panic. Plus the control
//! case (a valid file runs with exit 0) and a run stopped by the instability check (exit 1, files kept).
//!
//! The scenarios are the files in `tests/bad_inputs/`, each a valid base case with one thing broken.

use std::path::{Path, PathBuf};
use std::process::Command;

/// (file stem, substrings the error message must contain besides the file name)
const CASES: &[(&str, &[&str])] = &[
    ("courant_above_one", &["field `numerics.courant` = 1.5", "must be in (0, 1]"]),
    ("courant_above_friction_limit", &["field `numerics.courant` = 0.9", "sqrt(1 + z^2) - z = 0.519680"]),
    ("negative_stiffness", &["field `conductor.axial_stiffness_n` = -5", "> 0"]),
    ("zero_density", &["field `conductor.linear_density_kg_per_m` = 0", "> 0"]),
    ("nan_density", &["field `conductor.linear_density_kg_per_m` = NaN", "finite"]),
    // Issue 22: fields checked only where they were used.
    ("rated_tensile_strength_nan", &["field `conductor.rated_tensile_strength_n` = NaN", "must be in (0, 1e7] N"]),
    (
        "section_tension_unused_negative",
        &["field `section.horizontal_tension_n` = -28000", "must be in (0, 1e7] N (lines are strung"],
    ),
    ("one_segment", &["field `geometry.segments` = 1", "[2, 10000000]"]),
    ("negative_segments", &["line 9, column 12", "invalid value: integer `-4`"]),
    ("coincident_supports", &["field `geometry.right_support_m` = [0.0, 0.0, 0.0]", "apart"]),
    ("stiffness_twice", &["field `conductor.youngs_modulus_pa`", "not both"]),
    ("stiffness_missing", &["field `conductor.axial_stiffness_n` = (missing)"]),
    ("modulus_without_diameter", &["field `conductor.diameter_m` = (missing)", "youngs_modulus_pa"]),
    ("misspelt_field", &["line 12, column 1", "unknown field `courrant`"]),
    ("syntax_error", &["line 9, column 12"]),
    ("smoothing_too_large", &["field `numerics.smoothing` = 0.5", "[0, 0.25]"]),
    ("mu_out_of_range", &["field `numerics.mu` = 2", "[0, 1]"]),
    ("no_duration", &["field `duration` = (empty)"]),
    ("two_durations", &["field `duration.end_time_s` = 0.5", "not both"]),
    ("settle_fraction_above_one", &["kinetic_energy_fraction` = 2", "(0, 1)"]),
    ("pressure_missing", &["field `loads.wind.pressure_n_per_m` = (missing)"]),
    ("aerodynamic_without_diameter", &["field `conductor.diameter_m` = (missing)", "aerodynamic"]),
    ("zero_wind_direction", &["field `loads.wind.direction` = [0.0, 0.0, 0.0]", "non-zero"]),
    ("parabola_without_sag", &["field `initial.sag_m` = (missing)"]),
    ("negative_sag", &["field `initial.sag_m` = -3", "> 0"]),
    ("unknown_tension_law", &["line 5, column 15", "unknown variant `plastic`"]),
    ("snapshot_after_end", &["field `output.snapshot_times_s[1]` = 3", "end time"]),
    ("negative_sample_interval", &["field `output.sample_interval_s` = -0.1", "> 0"]),
    (
        "heat_linear_closure_next_to_free_end",
        &["field `events[0].boundary` = \"linear\"", "node 45, next to the free end node 46", "zero_flux"],
    ),
    ("section_and_geometry", &["field `section` = (given with [geometry])", "not both"]),
    ("section_ends_on_suspension", &["field `section.supports[2].kind` = \"suspension\"", "dead-ends"]),
    ("section_event_span_missing", &["field `events[0].span` = 5", "0 to 1"]),
    ("section_insulator_failure_at_dead_end", &["field `events[0].support` = 0", "suspension support"]),
    ("section_insulator_too_long", &["field `section.supports[1].insulator_length_m` = 35", "[0.01, 20] m"]),
    (
        "section_insulator_damping_negative",
        &["field `section.supports[1].insulator_damping_n_s` = -10000", "[0, 1e7] N s"],
    ),
    ("section_span_count", &["field `section.spans` = 3 tables", "2 for 3 supports"]),
    ("section_supports_out_of_order", &["field `section.supports[1]`", "advance along x2"]),
    ("section_without_stringing", &["field `section.spans[0].horizontal_tension_n` = (missing)"]),
    ("section_sag_and_length", &["field `section.spans[0].sag_m` = (given)", "not unstretched_length_m and sag_m"]),
    ("section_sag_too_large", &["field `section.spans[0].sag_m` = 250", "chord / 2"]),
    (
        "section_stringing_temperature_not_at_rest",
        &["field `section.stringing_temperature_k` = 288.15", "initial.shape = \"equilibrium\""],
    ),
    (
        "ground_profile_not_increasing",
        &["field `ground.profile_m` = [[0.0, 0.0], [500.0, 5.0], [400.0, 6.0]]", "strictly increasing"],
    ),
    ("ground_profile_above_line", &["field `ground.profile_m`", "initial node", "below the ground there"]),
    ("ground_height_and_profile", &["field `ground.profile_m`", "not both"]),
    ("mass_damping_too_large", &["field `numerics.mass_damping_per_s` = 1000000", "zeta dt < 1"]),
    (
        "ground_above_support",
        &["field `ground.height_m` = 5", "below both supports", "field `ground.restitution` = 1.5"],
    ),
    ("event_after_end", &["field `events[0].time_s` = 2", "end time"]),
    ("ice_range_out_of_bounds", &["field `events[0].range` = [0.5, 1.5]", "0 <= a < b <= 1"]),
    // Issue 10: each family of bad input the tester found (one file per case, named for what is wrong).
    ("ice_on_off_weightless_wire", &["field `conductor.linear_density_kg_per_m` = 1e-30", "[1e-3, 1e3] kg/m"]),
    (
        "ice_dropped_before_it_is_added",
        &["field `events[1].linear_density_kg_per_m` = -0.5", "segments 0..20 at 0.5 kg/m", "time order"],
    ),
    (
        "ice_dropped_beyond_its_range",
        &[
            "field `events[1].linear_density_kg_per_m` = -0.5",
            "segments 10..15 at 0.5 kg/m",
            "below conductor.linear_density_kg_per_m = 1 kg/m",
        ],
    ),
    ("ice_dropped_twice", &["field `events[2].linear_density_kg_per_m` = -0.3", "at 0.7", "kg/m"]),
    // Issue 24, the two-material law: it needs a catalogue conductor with stress-strain data (and a creep
    // curve for curve = "creep"); a curve belongs to it only.
    (
        "two_material_without_catalog",
        &["field `conductor.tension_law` = \"two_material\"", "needs conductor.catalog", "\"ACSR Drake\""],
    ),
    (
        "two_material_creep_without_creep_curve",
        &["field `conductor.curve` = \"creep\"", "\"ACSR Linnet\" has no creep curve", "use \"initial\""],
    ),
    (
        "curve_without_two_material",
        &["field `conductor.curve` = \"initial\"", "only with conductor.tension_law = \"two_material\""],
    ),
    ("curve_unknown", &["unknown variant `final`", "initial", "creep"]),
    // Issue 23, wind on ice: radial ice in exactly one form, in range, on a conductor with a diameter.
    ("ice_in_two_forms", &["field `events[0].linear_density_kg_per_m` = 0.5", "in one form", "not both"]),
    ("ice_thickness_negative", &["field `events[0].radial_thickness_m` = -0.01", "[0, 0.2] m"]),
    ("ice_density_out_of_range", &["field `events[0].density_kg_per_m3` = 1500", "[100, 1e3] kg/m^3", "glaze 900"]),
    ("ice_thickness_without_density", &["field `events[0].density_kg_per_m3` = (missing)", "radial_thickness_m"]),
    ("ice_without_amount", &["field `events[0].action` = \"ice\"", "needs linear_density_kg_per_m [kg/m], or"]),
    ("ice_thickness_without_diameter", &["field `conductor.diameter_m` = (missing)", "radial_thickness_m"]),
    ("ice_change_too_large", &["field `events[0].linear_density_kg_per_m` = 10000000", "[-1e3, 1e3] kg/m"]),
    ("support_with_four_components", &["line 7", "invalid length 4, expected exactly 3 components"]),
    ("uniform_load_with_two_components", &["line 18", "invalid length 2, expected exactly 3 components"]),
    ("ice_range_with_three_components", &["line 21, column 9", "invalid length 3, expected exactly 2 components"]),
    ("wind_direction_overflows", &["field `loads.wind.direction` = [1e308, 1e308, 0.0]", "within 1e6"]),
    ("supports_too_far_apart", &["field `geometry.right_support_m` = [0.0, 20000.0, 0.0]", "above 10000 m", "5.4 km"]),
    (
        "support_far_from_origin",
        &[
            "field `geometry.left_support_m` = [0.0, 0.0, 1000000000.0]",
            "within 1e5 m",
            "field `geometry.right_support_m`",
        ],
    ),
    ("parabola_on_vertical_chord", &["field `initial.shape` = parabola", "not vertical", "sags vertically"]),
    ("ground_cuts_initial_parabola", &["field `ground.height_m` = -10", "reaches x3 = -20 m", "below the ground"]),
    ("gust_period_below_time_step", &["field `events[0].period_s` = 0.0001", "dt = 8.0904e-3 s", "time steps"]),
    (
        "air_density_in_grams",
        &["field `loads.wind.air_density_kg_per_m3` = 1225", "kg/m^3, not g/m^3", "sea level 1.225"],
    ),
    (
        "temperature_without_expansion",
        &["field `events[0].action` = \"temperature\"", "thermal_expansion_per_k > 0", "changes nothing"],
    ),
    ("ice_range_narrower_than_a_segment", &["field `events[0].range` = [0.5, 0.51]", "selects no segment", "1/20"]),
    ("temperature_range_narrower_than_a_segment", &["field `events[0].range` = [0.2, 0.22]", "selects no segment"]),
    ("same_break_twice", &["field `events[1].at_fraction` = 0.5", "breaks segment 10", "events[0]", "breaks once"]),
    ("two_breaks_in_one_segment", &["field `events[1].at_fraction` = 0.52", "breaks segment 10", "already broken"]),
    ("wind_event_without_wind", &["field `events[0].action` = \"wind\"", "[loads.wind]"]),
    ("gust_event_without_wind", &["field `events[0].action` = \"gust\"", "[loads.wind]"]),
    ("ground_event_without_ground", &["field `events[0].action` = \"ground\"", "[ground]"]),
    ("tau_speed_overflows", &["field `output.tau_speed_m_per_s` = 1e308", "[1e-3, 1e3] m/s"]),
    (
        "unstretched_length_tiny",
        &["field `geometry.unstretched_length_m` = 1e-300", "[chord / 2, 100 chord] = [80, 16000] m"],
    ),
    ("unstretched_length_huge", &["field `geometry.unstretched_length_m` = 160000", "100 chord"]),
    (
        "cooling_to_negative_length",
        &["field `events[0].temperature_k` = 100", "-0.900000", "1 + alpha_t (u - u_ref)", "u >= 1500 K"],
    ),
    (
        "heating_hold_cools_to_zero_length",
        &["field `events[0].hold_temperature_k` = 1", "0.001000", "1 + alpha_t (u - u_ref)"],
    ),
    ("stiffness_absurd", &["field `conductor.axial_stiffness_n` = 1e30", "[1, 1e10] N"]),
    ("density_tiny", &["field `conductor.linear_density_kg_per_m` = 1e-30", "[1e-3, 1e3] kg/m"]),
    ("density_huge", &["field `conductor.linear_density_kg_per_m` = 100000", "[1e-3, 1e3] kg/m"]),
    ("youngs_modulus_absurd", &["field `conductor.youngs_modulus_pa` = 1e20", "[1e6, 1e12] Pa"]),
    ("diameter_huge", &["field `conductor.diameter_m` = 5", "[1e-4, 1] m"]),
    ("end_time_absurd", &["field `duration.end_time_s` = 1e300", "at most 1e8 s"]),
    ("settle_cap_absurd", &["field `duration.until_settled.max_time_s` = 1e300", "at most 1e8 s"]),
    ("sample_interval_absurd", &["field `output.sample_interval_s` = 1e300", "at most 1e8 s"]),
    ("wind_initial_scale_huge", &["field `loads.wind.initial_scale` = 10000000000", "at most 100"]),
    ("wind_scale_event_huge", &["field `events[0].scale` = 10000000000", "at most 100"]),
    ("gust_amplitude_huge", &["field `events[0].amplitude` = 10000000000", "at most 100"]),
    ("pressure_huge", &["field `loads.wind.pressure_n_per_m` = 1000000000", "1e4 N/m"]),
    ("uniform_load_huge", &["field `loads.uniform_load_n_per_m` = [0.0, 0.0, -1000000000.0]", "within 1e4 N/m"]),
    ("internal_friction_huge", &["field `numerics.eta_n_s` = 1e12", "1e9 N s"]),
    ("max_speed_absurd", &["field `numerics.max_speed_m_per_s` = 1e300", "1e7 m/s"]),
    ("normal_coefficient_huge", &["field `loads.wind.normal_coefficient` = 100", "at most 10"]),
    ("ramp_absurd", &["field `events[0].ramp_s` = 1e300", "1e8 s"]),
    ("thermal_expansion_too_large", &["field `conductor.thermal_expansion_per_k` = 1", "[0, 1e-3] 1/K"]),
    ("reference_temperature_zero", &["field `conductor.reference_temperature_k` = 0", "[173.15, 5000] K"]),
    ("heat_time_too_large", &["field `events[0].heat_time_per_s` = 1000000000", "(0, 1e3] 1/s"]),
    ("event_gate_unknown", &["line 26, column 8", "unknown variant `sideways`"]),
    ("event_number_as_text", &["line 20, column 15", "invalid type: string \"half\", expected a number"]),
    ("event_action_unknown", &["line 19, column 10", "unknown variant `melt`"]),
    ("event_field_unknown", &["line 21", "unknown field `gate`"]),
    ("nesting_too_deep", &["line 2", "max recursion depth"]),
    ("wind_speed_absurd", &["field `loads.wind.speed_m_per_s` = 1000000", "[0, 100] m/s", "km/h", "0 is still air"]),
    // Issue 23: 0 is still air, but a speed between 0 and 0.01 m/s would overflow the damping (2.6).
    ("wind_speed_tiny", &["field `loads.wind.speed_m_per_s` = 0.001", "must be 0 (still air) or at least 0.01 m/s"]),
    ("wind_ramp_negative", &["field `loads.wind.ramp_s` = -5", "must be a finite number >= 0, at most 1e8 s"]),
    ("wind_event_ramp_nan", &["field `events[0].ramp_s` = NaN", "at most 1e8 s"]),
    ("probe_named_mid", &["field `output.probes[0].name` = \"mid\"", "letters, digits and _ only"]),
    ("event_time_negative", &["field `events[0].time_s` = -1", "[0, end time]"]),
    ("break_at_the_support", &["field `events[0].at_fraction` = 1", "(0, 1)"]),
    ("peaks_after_end", &["field `output.peaks_from_s` = 5", "[0, end time]"]),
    ("not_utf8", &["line 4, column 36", "not valid UTF-8", "byte 0xb0"]),
    ("thermal_unknown_conductor", &["field `thermal.conductor` = \"ACSR Condor\"", "available: ACSR Drake"]),
    ("thermal_current_back_in_time", &["field `thermal.current_a[2][0]` = 300", "must not decrease"]),
    ("thermal_with_temperature_event", &["field `events[0].action`", "must not be combined with [thermal]"]),
    ("thermal_air_in_celsius", &["field `thermal.weather.air_temperature_k` = 25", "[200, 350] K"]),
    ("rating_clearance_without_ground", &["field `rating.min_clearance_m` = 8", "needs a [ground]"]),
    ("deicing_varying_current", &["field `thermal.current_a`", "must be constant with [thermal.deicing]"]),
    ("thermal_history_too_long", &["field `thermal.step_s` = 1", "must be at least 10.000 s"]),
    // Issue 22: conductors beyond the catalogue, and the span's inclination.
    ("thermal_conductor_diameter_in_mm", &["field `thermal.conductor.diameter_m` = 28.14", "[1e-3, 0.2] m"]),
    ("thermal_inclination_with_ieee738", &["field `thermal.inclination_deg` = 10", "CIGRE TB 601 only"]),
    (
        "thermal_conductor_catalog_missing",
        &["field `thermal.conductor_catalog` = \"no_such_catalogue.toml\"", "readable conductor catalogue"],
    ),
    (
        "thermal_conductor_catalog_bad_entry",
        &["emissivity_above_one.toml (conductor_catalog of", "field `conductor[0].emissivity` = 1.5", "[0, 1]"],
    ),
    // Issue 22: messages that name the field as written (with its array index, at the value's line, every
    // missing field), and inputs that were accepted silently.
    (
        "section_support_fields_missing",
        &[
            "line 12, column 3",
            "field `section.supports[1]`: missing fields `insulator_length_m`, `insulator_mass_kg`, \
             `insulator_stiffness_n`",
        ],
    ),
    (
        "section_support_value_as_text",
        &["line 13, column 26", "field `section.supports[1].insulator_length_m`: invalid type: string \"3.5\""],
    ),
    ("section_segments_per_span_zero", &["field `section.segments_per_span` = 0", "[2, 1000000]"]),
    (
        "section_tension_above_rts",
        &["field `section.horizontal_tension_n` = 150000", "below conductor.rated_tensile_strength_n = 140000 N"],
    ),
    ("reference_temperature_in_celsius", &["field `conductor.reference_temperature_k` = 15", "not Celsius"]),
    // Issue 23: temperatures in degrees Celsius (`_c` twins), refused in the unit written.
    (
        "reference_temperature_kelvin_and_celsius",
        &["field `conductor.reference_temperature_c` = 15.0", "`conductor.reference_temperature_k` is given too"],
    ),
    (
        "reference_temperature_celsius_below_absolute_zero",
        &["field `conductor.reference_temperature_c` = -300 is not allowed: must be in [-100, 4726.85] C"],
    ),
    (
        "heat_conduction_without_expansion",
        &["field `events[0].action` = \"heat_conduction\"", "thermal_expansion_per_k > 0"],
    ),
    ("heat_conduction_above_budget", &["heat node updates", "lower events[0].heat_time_per_s"]),
    (
        "ground_profile_point_with_three_numbers",
        &["line 15, column 13", "field `ground.profile_m`: point [1] has 3 numbers"],
    ),
    ("thermal_case_given_to_run", &["a thermal case", "`ohl thermal`"]),
    // Issue 25: [short_circuit] of a line scenario.
    (
        "short_circuit_unknown_phase",
        &["field `short_circuit.phases[2]` = \"X\"", "must name a conductor of the line: A, B, C"],
    ),
    ("short_circuit_phase_twice", &["field `short_circuit.phases[2]` = \"A\"", "already named"]),
    ("short_circuit_contact_restitution", &["field `short_circuit.contact_restitution` = 1.5", "must be in (0, 1]"]),
    (
        "short_circuit_contact_stiffness",
        &["field `short_circuit.contact_stiffness_n_per_m2` = 1e15", "must be in [1e4, 1e12] N/m^2"],
    ),
    (
        "short_circuit_current_out_of_range",
        &["field `short_circuit.initial_current_a` = 19000000", "must be in [100, 300000] A"],
    ),
    ("short_circuit_kappa_and_r_over_x", &["field `short_circuit.r_over_x` = 0.07", "not both"]),
    ("short_circuit_peak_factor_above_two", &["field `short_circuit.peak_factor` = 2.5", "(1.02, 2)"]),
    ("short_circuit_start_after_end", &["field `short_circuit.start_s` = 0.5", "before the end time"]),
    ("short_circuit_two_phases_for_three_phase", &["field `short_circuit.phases`", "must name 3 conductors"]),
    (
        "short_circuit_reclose_negative_dead_time",
        &["field `short_circuit.reclose.dead_time_s` = -0.3", "must be in [0.05, 600] s"],
    ),
    ("sagtension_case_given_to_run", &["a sag-tension case", "`ohl sagtension`"]),
    // Droppers (docs/line.md).
    (
        "dropper_from_unknown_conductor",
        &["field `line.conductors[1].dropper.from` = \"bus\"", "listed before this one"],
    ),
    ("dropper_fraction_outside_the_span", &["field `line.conductors[1].dropper.at_fraction` = 1.2", "(0, 1)"]),
    (
        "dropper_shorter_than_its_chord",
        &["field `line.conductors[1].dropper.length_m` = 3", "must be in [3.8989, 1000] m", "at least the distance"],
    ),
    (
        "dropper_slack_and_plumb",
        &["field `line.conductors[1].dropper.to_m` = [0.0, 7.5, 5.0]", "plumb below the joint", "offset the terminal"],
    ),
];

/// Cases for `ohl thermal` (file stem, message substrings; exit code 2).
const THERMAL_CASES: &[(&str, &[&str])] = &[
    ("thermal_case_asks_nothing", &["field `current_a` = (missing)", "the case asks nothing"]),
    (
        "thermal_case_max_below_air",
        &["field `max_temperature_k[1]` = 303.15", "above the air temperature weather.air_temperature_k = 313.15 K"],
    ),
    (
        "thermal_case_schedule_point_with_three_numbers",
        &["line 26, column 13", "field `transient.current_a`: point [1] has 3 numbers"],
    ),
    (
        "thermal_case_air_celsius_out_of_range",
        &["field `weather.air_temperature_c` = 95 is not allowed: must be in [-73.15, 76.85] C"],
    ),
    (
        "thermal_case_limit_celsius_below_absolute_zero",
        &["field `transient.limit_c` = -300 is not allowed: must be in [-73.15, 326.85] C"],
    ),
    ("thermal_case_air_temperature_missing", &["missing field `air_temperature_k` (or `air_temperature_c`)"]),
    ("thermal_case_transient_above_budget", &["field `transient.step_s` = 0.001", "at least 1 s"]),
    ("thermal_case_deicing_step_tiny", &["field `deicing.step_s` = 0.001", "at least 0.00864 s"]),
    ("scenario_given_to_thermal", &["a wire scenario ([conductor]), not a thermal case", "`ohl run`"]),
    ("sagtension_case_given_to_thermal", &["a sag-tension case", "`ohl sagtension`"]),
    (
        "thermal_case_measured_radiation_under_ieee",
        &["field `weather.sun.measured_global_w_per_m2` = 900", "only with standard = \"cigre601\""],
    ),
];

/// Cases for `ohl sagtension` (file stem, message substrings; exit code 2).
const SAGTENSION_CASES: &[(&str, &[&str])] = &[
    (
        "sagtension_temperature_celsius_out_of_range",
        &["field `condition[0].temperature_c` = 400 is not allowed: must be in [-100, 300] C"],
    ),
    ("sagtension_span_and_ruling_span", &["field `ruling_span` = (given with [span])", "not both"]),
    ("sagtension_tension_and_sag", &["field `stringing`", "give one of tension_n, tension_fraction_of_rts and sag_m"]),
    (
        "sagtension_unknown_load_case",
        &["field `heavy_load.case` = \"nesc_extreme\"", "must be a load case: nesc_heavy"],
    ),
    (
        "sagtension_iec_case_without_values",
        &["field `condition[0].case` = \"iec60826_ice_wind\"", "leaves temperature_k, ice_thickness_m"],
    ),
    ("sagtension_range_reversed", &["field `conditions.to_temperature_c` = -20", "the range runs upwards"]),
    ("sagtension_clearance_above_supports", &["field `clearance.min_clearance_m` = 30", "mid-span, 25 m"]),
    ("sagtension_unknown_conductor", &["field `conductor.catalog` = \"ACSR Dinosaur\"", "available: ACSR Drake"]),
    ("sagtension_asks_nothing", &["field `condition` = (missing)", "the case asks nothing"]),
    ("sagtension_tension_above_rts", &["field `stringing.tension_n` = 150000", "rated tensile strength 138800 N"]),
];

/// Heat-conduction cases (`ohl paper CASE --cases tests/bad_inputs`): (file stem, message substrings).
const PAPER_CASES: &[(&str, &[&str])] = &[
    ("heat_tiny_temperature_scale", &["field `rod.temperature_scale_k` = 1e-300", "[1, 1e4] K", "overflow"]),
    ("heat_temperature_absurd", &["field `rod.left_temperature_k` = 1e300", "1e4 K"]),
    ("heat_segments_above_budget", &["field `rod.segments` = 100000", "2.000e16 node updates", "budget"]),
    ("heat_step_ratio_above_budget", &["field `runs[3].step_ratio` = 0.000000001", "at least 0.00006375"]),
];

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_inputs")
}

fn ohl(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_ohl")).args(args).output().expect("run ohl");
    (
        out.status.code().expect("ohl was killed by a signal"),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ohl-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

#[test]
fn every_invalid_scenario_is_refused_with_a_precise_message() {
    assert!(CASES.len() + PAPER_CASES.len() >= 80);
    let out = tmp("bad");
    for (stem, needles) in CASES {
        let file = dir().join(format!("{stem}.toml"));
        let (code, _, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(code, 2, "{stem}: exit code {code}, stderr:\n{err}");
        assert!(err.contains(&format!("{stem}.toml")), "{stem}: message does not name the file:\n{err}");
        for n in *needles {
            assert!(err.contains(n), "{stem}: message lacks `{n}`:\n{err}");
        }
        assert!(!err.contains("panicked"), "{stem}: panicked:\n{err}");
        assert!(!out.join("timeseries.csv").exists(), "{stem}: a refused scenario must not start a run");
    }
}

#[test]
fn every_invalid_heat_case_is_refused_with_a_precise_message() {
    let out = tmp("bad-heat");
    for (stem, needles) in PAPER_CASES {
        let (code, stdout, err) =
            ohl(&["paper", stem, "--cases", dir().to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(code, 2, "{stem}: exit code {code}, stderr:\n{err}");
        // Only the refusal (on stderr): no empty results table, no summary of zero values.
        assert!(stdout.trim().is_empty(), "{stem}: a refused case prints nothing on stdout:\n{stdout}");
        assert!(err.contains(&format!("{stem}.toml")), "{stem}: message does not name the file:\n{err}");
        for n in *needles {
            assert!(err.contains(n), "{stem}: message lacks `{n}`:\n{err}");
        }
        assert!(!err.contains("panicked"), "{stem}: panicked:\n{err}");
    }
}

#[test]
fn every_invalid_thermal_case_is_refused_with_a_precise_message() {
    let out = tmp("bad-thermal");
    for (stem, needles) in THERMAL_CASES {
        let file = dir().join(format!("{stem}.toml"));
        let (code, _, err) = ohl(&["thermal", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(code, 2, "{stem}: exit code {code}, stderr:\n{err}");
        assert!(err.contains(&format!("{stem}.toml")), "{stem}: message does not name the file:\n{err}");
        for n in *needles {
            assert!(err.contains(n), "{stem}: message lacks `{n}`:\n{err}");
        }
        assert!(!err.contains("panicked"), "{stem}: panicked:\n{err}");
        assert!(!out.exists(), "{stem}: a refused case must not write anything");
    }
}

#[test]
fn every_invalid_sagtension_case_is_refused_with_a_precise_message() {
    let out = tmp("bad-sagtension");
    for (stem, needles) in SAGTENSION_CASES {
        let file = dir().join(format!("{stem}.toml"));
        let (code, stdout, err) = ohl(&["sagtension", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
        assert_eq!(code, 2, "{stem}: exit code {code}, stderr:\n{err}");
        assert!(stdout.trim().is_empty(), "{stem}: a refused case prints no table:\n{stdout}");
        assert!(err.contains(&format!("{stem}.toml")), "{stem}: message does not name the file:\n{err}");
        for n in *needles {
            assert!(err.contains(n), "{stem}: message lacks `{n}`:\n{err}");
        }
        assert!(!err.contains("panicked"), "{stem}: panicked:\n{err}");
        assert!(!out.exists(), "{stem}: a refused case must not write anything");
    }
}

#[test]
fn a_negative_shard_or_thread_count_is_named_by_its_option() {
    let base = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/sweep/drake_400m_wind.toml");
    let out = tmp("shard");
    for (flag, value, needle) in [
        ("--shard", "-1/2", "--shard -1/2: K = \"-1\" is not a whole number >= 0"),
        ("--threads", "-1", "invalid value '-1' for '--threads <THREADS>'"),
    ] {
        let args = ["sweep", base.to_str().unwrap(), flag, value, "--vary", "loads.wind.speed_m_per_s=10,20"];
        let (code, _, err) = ohl(&[&args[..], &["--out", out.to_str().unwrap()]].concat());
        assert_eq!(code, 2, "{flag} {value}: stderr:\n{err}");
        assert!(err.contains(needle), "{flag} {value}: {err}");
        assert!(!out.exists(), "nothing is written for refused arguments");
    }
}

#[test]
fn every_file_of_the_directory_is_a_case() {
    let mut listed: Vec<&str> =
        CASES.iter().chain(PAPER_CASES).chain(THERMAL_CASES).chain(SAGTENSION_CASES).map(|c| c.0).collect();
    listed.push("valid");
    listed.sort_unstable();
    let mut files: Vec<String> = std::fs::read_dir(dir())
        .unwrap()
        .map(|e| e.unwrap().path().file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    files.sort_unstable();
    assert_eq!(files, listed, "every file of tests/bad_inputs is listed once, and every case has its file");
}

#[test]
fn the_valid_control_case_runs() {
    let out = tmp("valid");
    let file = dir().join("valid.toml");
    let (code, stdout, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "stderr:\n{err}");
    assert!(stdout.contains("completed"));
    for f in ["timeseries.csv", "snapshots.csv", "summary.json"] {
        assert!(out.join(f).exists(), "{f} missing");
    }
}

#[test]
fn a_missing_file_is_refused_with_exit_code_2() {
    let (code, _, err) = ohl(&["run", "no/such/scenario.toml", "--out", tmp("missing").to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("no/such/scenario.toml") && err.contains("cannot read"), "{err}");
}

#[test]
fn an_instability_stops_the_run_with_time_node_and_reason_and_keeps_the_output() {
    // A free fall under gravity passes 2 m/s after about 0.2 s: with the speed bound set to 2 m/s the
    // run must stop there (exit 1), name the node and the reason, and leave readable files.
    let out = tmp("unstable");
    let text = std::fs::read_to_string(dir().join("valid.toml"))
        .unwrap()
        .replace("courant = 0.9", "courant = 0.9\nmax_speed_m_per_s = 2.0");
    let file = out.with_extension("toml");
    std::fs::write(&file, text).unwrap();
    let (code, _, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 1, "stderr:\n{err}");
    assert!(err.contains("unstable at t = ") && err.contains("node ") && err.contains("exceeds the bound"), "{err}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["status"], "unstable");
    let t_fail = summary["instability"]["time_s"].as_f64().unwrap();
    // Free fall: v = g t reaches 2 m/s at t = 0.204 s; the first node to exceed it does so within a few
    // steps of that (the mid-span falls freely until the support waves arrive).
    assert!((0.19..0.25).contains(&t_fail), "failed at {t_fail} s");
    let series = std::fs::read_to_string(out.join("timeseries.csv")).unwrap();
    assert!(series.lines().count() >= 4, "time series so far was not kept:\n{series}");
}

#[test]
fn a_heat_case_is_refused_by_run_with_a_pointer_to_paper() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../paper_cases/heat_two_halves.toml");
    let out = tmp("heat");
    let (code, _, err) = ohl(&["run", file.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 2, "stderr:\n{err}");
    assert!(err.contains("heat_two_halves.toml") && err.contains("`ohl paper heat_two_halves`"), "{err}");
    assert!(!out.exists(), "nothing is written for a refused case");
}

#[test]
fn a_load_case_refuses_to_guess_and_prints_a_valid_scenario_when_complete() {
    // IEC 60826 leaves the ice, the coincident wind, the drag coefficient and the temperature to the
    // designer: without them the command names the missing option and exits 2.
    let (code, _, err) = ohl(&["load-case", "iec60826_ice_wind", "--radial-ice-m", "0.015"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--wind-pressure-pa or --wind-speed-m-per-s") && err.contains("return period"), "{err}");
    let (code, _, err) = ohl(&["load-case", "nesc_extreme"]);
    assert_eq!(code, 2);
    assert!(err.contains("nesc_heavy, nesc_medium, nesc_light"), "{err}");
    // NESC heavy on Drake: the fragment, put under a one-span scenario, validates and holds the district's
    // numbers (12.5 mm, 913 kg/m^3, 190 Pa -> 17.6126 m/s).
    let (code, out, err) = ohl(&["load-case", "nesc_heavy", "--conductor", "ACSR Drake"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("radial_thickness_m = 0.0125") && out.contains("density_kg_per_m3 = 913.0"), "{out}");
    assert!(out.contains("speed_m_per_s = 17.612611") && out.contains("K = 4.4 N/m"), "{out}");
    let scenario = format!(
        "[conductor]\ncatalog = \"ACSR Drake\"\n[geometry]\nleft_support_m = [0.0, 0.0, 0.0]\n\
         right_support_m = [0.0, 400.0, 0.0]\nunstretched_length_m = 401.0\nsegments = 40\n\
         [initial]\nshape = \"equilibrium\"\n[duration]\nend_time_s = 0.01\n{out}"
    );
    let s = ohl::scenario::parse(&scenario, "<load-case>").expect("the fragment parses");
    let plan = ohl::scenario::plan(&s, "<load-case>").expect("the fragment validates and builds");
    // The shell is on the wire at the static start: the wind acts on d + 2 t.
    let k = plan.solver.wire().wind_diameter_factor[0];
    assert_eq!(k, (0.02814 + 0.025) / 0.02814);
}

/// `ohl bench --fixed` past the episode length that keeps an undamped configuration stable (plane_weight
/// at N = 5000 goes unstable near step 3730, docs/paper_notes.md): an error naming the time and node, exit
/// code 1 as for an unstable run, not a panic.
#[test]
fn bench_fixed_beyond_an_episode_reports_the_instability() {
    let (code, _out, err) = ohl(&["bench", "--fixed", "plane_weight:5000:6000"]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("unstable at t =") && err.contains("node"), "{err}");
    assert!(err.contains("4000 steps"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}
