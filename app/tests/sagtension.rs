//! `ohl sagtension` on the two example cases of `examples/sagtension/`: the printed table and the files
//! hold the library's numbers (the table solved again here through `ohl::scenario::sagtension_table`, the
//! printed values compared at the printed precision, the CSV's exactly: `f64` written by `to_string` reads
//! back to the same bits), and the files are there with their columns.

use std::path::{Path, PathBuf};
use std::process::Command;

use ohl::scenario::sagtension;
use ohl::scenario::sagtension_table;
use ohl_app::sagtension::{CSV_COLUMNS, support_tension_n};

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/sagtension").join(name)
}

fn run(case: &Path, tag: &str) -> (String, PathBuf) {
    let out = std::env::temp_dir().join(format!("ohl-test-{}-sagtension-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = Command::new(env!("CARGO_BIN_EXE_ohl"))
        .args(["sagtension", case.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .output()
        .expect("run ohl");
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(0), "stderr:\n{stderr}");
    (String::from_utf8_lossy(&o.stdout).into_owned(), out)
}

/// The printed table's data lines (the lines with a state name and nine columns), split on whitespace from
/// the right: state, H, sag, T_sup, %RTS, Al, core, knee.
fn printed_rows(stdout: &str) -> Vec<Vec<String>> {
    let states = ["initial", "after_creep", "after_load", "final="];
    stdout
        .lines()
        .filter_map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            let tail = w.len().checked_sub(8).map(|k| &w[k..])?;
            states.iter().any(|s| tail[0].starts_with(s)).then(|| tail.iter().map(|s| s.to_string()).collect())
        })
        .collect()
}

fn check_case(file: &str, tag: &str) {
    let case = example(file);
    let (stdout, out) = run(&case, tag);
    let (_, resolved) = sagtension::load(&case).unwrap();
    let table = sagtension_table::solve(&resolved).unwrap();
    let rows = printed_rows(&stdout);
    assert_eq!(rows.len(), resolved.conditions.len() * table.states.len(), "{stdout}");
    assert_eq!(rows.len(), table.rows.len());
    for (p, r) in rows.iter().zip(&table.rows) {
        let want = [
            format!("{:.3}", r.horizontal_tension_n / 1e3),
            format!("{:.3}", r.sag_midspan_m),
            format!("{:.3}", support_tension_n(r) / 1e3),
            format!("{:.2}", 100.0 * r.max_tension_fraction_rts),
            format!("{:.2}", r.outer_stress_pa / 1e6 + 0.0),
            format!("{:.2}", r.core_stress_pa / 1e6 + 0.0),
            (if r.knee_passed { "yes" } else { "no" }).to_string(),
        ];
        assert_eq!(&p[1..], &want[..], "row {p:?}");
        assert!(p[0].starts_with(r.state.name()), "{p:?}");
    }
    for (state, k) in &table.knee_k {
        let line = format!("knee-point temperature, {}: {:.2} C", state.name(), k.as_ref().unwrap() - 273.15);
        assert!(stdout.contains(&line), "missing `{line}`:\n{stdout}");
    }
    // sagtension.csv: the columns, one line per row, the library's numbers exactly.
    let mut csv = csv::Reader::from_path(out.join("sagtension.csv")).unwrap();
    assert_eq!(csv.headers().unwrap().iter().collect::<Vec<_>>(), CSV_COLUMNS);
    let recs: Vec<csv::StringRecord> = csv.records().map(Result::unwrap).collect();
    assert_eq!(recs.len(), table.rows.len());
    let col = |name: &str| CSV_COLUMNS.iter().position(|c| *c == name).unwrap();
    for (rec, r) in recs.iter().zip(&table.rows) {
        assert_eq!(rec[col("horizontal_tension_n")].parse::<f64>().unwrap(), r.horizontal_tension_n);
        assert_eq!(rec[col("sag_m")].parse::<f64>().unwrap(), r.sag_midspan_m);
        assert_eq!(rec[col("core_stress_pa")].parse::<f64>().unwrap(), r.core_stress_pa);
        assert_eq!(&rec[col("state")], r.state.name());
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("sagtension.json")).unwrap()).unwrap();
    assert_eq!(json["rows"].as_array().unwrap().len(), table.rows.len());
    assert_eq!(json["final_is"], table.final_is.name());
    // Each span's sag: the library's (a section's spans at the ruling span's H), and for a section
    // within 1 % of the parabolic ratio sag_r (l_i / l_r)^2 (the ruling-span rule the spans follow).
    for ((j, r), sags) in json["rows"].as_array().unwrap().iter().zip(&table.rows).zip(&table.span_sags_m) {
        let written: Vec<f64> = j["span_sags_m"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
        assert_eq!(written.len(), resolved.lengths_m.len());
        for ((w, s), l) in written.iter().zip(sags).zip(&resolved.lengths_m) {
            // serde_json writes the shortest round-trip form, but its default parser may land one ulp off.
            assert!((w - s).abs() <= 2.0 * f64::EPSILON * s.abs(), "{w} != {s}");
            let parabolic = r.sag_midspan_m * (l / table.span_m).powi(2);
            assert!((s - parabolic).abs() < 0.01 * parabolic, "span {l} m: {s} vs parabolic {parabolic}");
        }
    }
    for ext in ["png", "svg"] {
        let f = out.join(format!("sag_vs_temperature.{ext}"));
        assert!(std::fs::metadata(&f).is_ok_and(|m| m.len() > 1000), "{} missing or empty", f.display());
    }
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn the_handbook_span_prints_and_writes_the_librarys_table() {
    check_case("drake_700ft.toml", "700ft");
}

#[test]
fn the_ruling_span_section_prints_and_writes_the_librarys_table_and_the_sag_limit_temperatures() {
    check_case("drake_ruling_span.toml", "ruling");
    let case = example("drake_ruling_span.toml");
    let (stdout, _) = run(&case, "ruling-limit");
    let (_, resolved) = sagtension::load(&case).unwrap();
    let table = sagtension_table::solve(&resolved).unwrap();
    // The limit of the longest span (400 m): 25 m - 10 m = 15 m; reached where that span, at the ruling
    // span's H, sags 15 m (to the search's 1e-10 K: 1e-6 m covers the sag's change over it).
    assert_eq!(table.sag_limit_m, Some(15.0));
    let strung = sagtension_table::strung(&resolved, resolved.law().0).unwrap();
    assert_eq!(table.limit_k.len(), table.states.len());
    for (state, k) in &table.limit_k {
        let t = k.as_ref().unwrap() - 273.15;
        assert!(stdout.contains(&format!("reached, {}: {t:.2} C", state.name())), "{stdout}");
        let sag = sagtension_table::sag_at(&strung, *state, t + 273.15, Some(400.0)).unwrap();
        assert!((sag - 15.0).abs() < 1e-6, "{}: {sag} m", state.name());
    }
}
