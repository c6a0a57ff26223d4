//! Every example of `examples/` runs: thermal cases through `ohl thermal` (exit 0, `thermal.json`
//! written), scenarios with a `[rating]` table through `ohl rating` (exit 0, `rating.json`), other
//! scenarios through `ohl run` (exit 0, `summary.json`). Their numbers are checked elsewhere
//! (`tests/rating.rs`, `app/tests/cases.rs`, the `thermal` study); this keeps every example runnable.

use std::path::Path;
use std::process::Command;

#[test]
fn every_example_runs() {
    let repo = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_path_buf();
    let mut files: Vec<_> = std::fs::read_dir(repo.join("examples/thermal"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    assert!(files.len() >= 3, "examples: {files:?}");
    for f in &files {
        let text = std::fs::read_to_string(f).unwrap();
        let out = std::env::temp_dir().join(format!(
            "ohl-example-{}-{}",
            std::process::id(),
            f.file_stem().unwrap().to_string_lossy()
        ));
        let (command, written) = if text.contains("[rating]") {
            ("rating", "rating.json")
        } else if text.contains("[conductor]") {
            ("run", "summary.json")
        } else {
            ("thermal", "thermal.json")
        };
        let o = Command::new(env!("CARGO_BIN_EXE_ohl")).arg(command).arg(f).arg("--out").arg(&out).output().unwrap();
        println!("{} {}: {}", command, f.display(), String::from_utf8_lossy(&o.stdout));
        assert!(o.status.success(), "{}: {}", f.display(), String::from_utf8_lossy(&o.stderr));
        assert!(out.join(written).exists(), "{} wrote no {written}", f.display());
    }
}
