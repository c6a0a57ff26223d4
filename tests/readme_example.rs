//! The commented scenario in the README is a valid scenario: documentation that a user copies must parse
//! and pass validation, and its stated defaults must be the ones the code applies.

use std::path::Path;

fn toml_blocks(readme: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<String> = None;
    for line in readme.lines() {
        match (&mut current, line.trim_start()) {
            (None, l) if l.starts_with("```toml") => current = Some(String::new()),
            (Some(_), l) if l.starts_with("```") => blocks.push(current.take().unwrap_or_default()),
            (Some(b), _) => {
                b.push_str(line);
                b.push('\n');
            }
            (None, _) => {}
        }
    }
    blocks
}

#[test]
fn the_readme_scenario_example_is_valid_and_runs() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).expect("README");
    let blocks = toml_blocks(&readme);
    assert!(blocks.len() >= 2, "the README has the scenario example and the events example");
    let sc = ohl::scenario::parse(&blocks[0], "README.md (first toml block)").unwrap_or_else(|e| panic!("{e}"));
    // The events example is a fragment: appended to the scenario it must parse and validate too.
    let with_events = format!("{}\n{}", blocks[0], blocks[1]);
    ohl::scenario::parse(&with_events, "README.md (events block)").unwrap_or_else(|e| panic!("{e}"));
    // And the scenario runs (a short piece of it) without instability.
    let mut plan = ohl::scenario::plan(&sc, "README.md").unwrap_or_else(|e| panic!("{e}"));
    plan.stop = ohl::scenario::build::Stop::EndTime(0.5);
    let opts = ohl::run::RunOptions { out_dir: None, record: false };
    ohl::run::run(plan, &opts).unwrap_or_else(|e| panic!("{e}"));
}

/// The README's line example (the block with `[line]`) is a valid line scenario and runs.
#[test]
fn the_readme_line_example_is_valid_and_runs() {
    let readme = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).expect("README");
    let blocks: Vec<String> = toml_blocks(&readme).into_iter().filter(|b| ohl::scenario::line::is_line(b)).collect();
    assert_eq!(blocks.len(), 1, "the README has one line example");
    let file = "README.md ([line] block)";
    let sc = ohl::scenario::line::parse(&blocks[0], file).unwrap_or_else(|e| panic!("{e}"));
    let mut plan = ohl::scenario::line::plan(&sc, file).unwrap_or_else(|e| panic!("{e}"));
    plan.stop = ohl::scenario::build::Stop::EndTime(0.5);
    ohl::run::line::run_line(plan, None).unwrap_or_else(|e| panic!("{e}"));
}
