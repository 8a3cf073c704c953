//! The verification pages (docs/verification/) and their data files
//! (docs/verification/data/): each page's table is made from its data file, and the code
//! reproduces the data file's numbers within the file's tolerances, so that page, data
//! and code cannot drift apart. When a change moves a number, the data file is
//! re-measured (its header gives the command) and the failure prints the page's new table.

use serde::Deserialize;
use sph_impact::verify::Problem;
use std::collections::BTreeMap;
use std::path::PathBuf;

fn docs() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../docs/verification")
}

/// One resolution's reference numbers: `verify PROBLEM --json` keys.
#[derive(Debug, Deserialize)]
struct Run {
    resolution: usize,
    /// Run by `cargo test` (false: too slow for it; `--ignored` runs it).
    tested: bool,
    #[serde(flatten)]
    values: BTreeMap<String, f64>,
}

/// A data file: the problem, the absolute tolerance of each key, the runs, and the
/// columns of the page's table (for problems without a table of their own).
#[derive(Debug, Deserialize)]
struct Data {
    problem: String,
    /// `rz` for a problem's axisymmetric form, `rings` for the Taylor rod placed as
    /// revolved rings (the CLI's `--geometry`); absent for the problem's own geometry.
    #[serde(default)]
    geometry: Option<String>,
    /// The page that shows the table, when it is not the one named as the data file
    /// (a page with two tables, one per data file).
    #[serde(default)]
    page: Option<String>,
    tolerance: BTreeMap<String, f64>,
    run: Vec<Run>,
    #[serde(default)]
    column: Vec<Column>,
}

/// A column of the page's table: a key, its heading, and how it is printed: `sci4`
/// (1.2345e-2), `fixedN` (N decimals), `gigaN` and `megaN` (/10⁹ and /10⁶, N decimals:
/// Pa as GPa or MPa), `signedN`
/// (N decimals with a sign), `percentN` (× 100, N decimals, a sign and " %"), `integer`.
#[derive(Debug, Deserialize)]
struct Column {
    key: String,
    label: String,
    format: String,
}

impl Column {
    fn print(&self, x: f64) -> String {
        let digits = |prefix: &str| -> usize {
            self.format[prefix.len()..]
                .parse()
                .unwrap_or_else(|_| panic!("column {}: format {}", self.key, self.format))
        };
        match self.format.as_str() {
            "sci4" => {
                let s = format!("{x:.4e}");
                s.strip_prefix('-').map_or(s.clone(), |m| format!("−{m}"))
            }
            "integer" => format!("{x:.0}"),
            f if f.starts_with("fixed") => format!("{:.*}", digits("fixed"), x),
            f if f.starts_with("giga") => format!("{:.*}", digits("giga"), x / 1e9),
            f if f.starts_with("mega") => format!("{:.*}", digits("mega"), x / 1e6),
            f if f.starts_with("signed") => signed(x, digits("signed")),
            f if f.starts_with("percent") => format!("{} %", signed(100.0 * x, digits("percent"))),
            f => panic!("column {}: unknown format {f}", self.key),
        }
    }
}

/// The page's table from the data file's columns: one row per run.
fn column_table(d: &Data) -> String {
    let mut t = String::from("| N |");
    let mut rule = String::from("|---|");
    for c in &d.column {
        t += &format!(" {} |", c.label);
        rule += "---|";
    }
    t += &format!("\n{rule}\n");
    for r in &d.run {
        t += &format!("| {} |", r.resolution);
        for c in &d.column {
            t += &format!(" {} |", c.print(r.values[&c.key]));
        }
        t += "\n";
    }
    t
}

/// The checks of one page: every value has a tolerance, the page shows `table`, and the
/// code reproduces the tested runs.
fn check_problem(name: &str, problem: Problem, table: impl Fn(&Data) -> String) {
    let d = data(name);
    assert_eq!(
        d.problem.replace('_', "-"),
        problem.name(),
        "{name}: problem"
    );
    for r in &d.run {
        for key in r.values.keys() {
            assert!(
                d.tolerance.contains_key(key),
                "{name}: no tolerance for {key}"
            );
        }
    }
    check_page(d.page.as_deref().unwrap_or(name), &table(&d));
    check_runs(name, &d, problem, false);
}

fn data(name: &str) -> Data {
    let path = docs().join("data").join(format!("{name}.toml"));
    let text = std::fs::read_to_string(&path).unwrap();
    toml::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A signed number with a Unicode minus, `decimals` after the point.
fn signed(x: f64, decimals: usize) -> String {
    let s = format!("{:+.*}", decimals, x);
    s.replacen('-', "−", 1)
}

/// The page's table of a 1-D Riemann problem's runs: L1(ρ) with its observed order,
/// the star state's errors, the shock's error in local spacings, the steps.
fn riemann_table(d: &Data) -> String {
    let mut t = String::from(
        "| N | L1(ρ) | order | p* error | u* error | shock error (local spacings) | steps |\n\
         |---|---|---|---|---|---|---|\n",
    );
    let mut previous: Option<(usize, f64)> = None;
    for r in &d.run {
        let v = |k: &str| r.values[k];
        let l1 = v("l1_rho");
        let order = previous.map_or("–".to_string(), |(n0, l0)| {
            format!(
                "{:.2}",
                (l0 / l1).ln() / (r.resolution as f64 / n0 as f64).ln()
            )
        });
        t += &format!(
            "| {} | {l1:.4e} | {} | {} % | {} % | {} | {} |\n",
            r.resolution,
            order,
            signed(100.0 * v("p_star_error_relative"), 2),
            signed(100.0 * v("u_star_error_relative"), 2),
            signed(v("shock_error_in_spacings"), 2),
            v("steps")
        );
        previous = Some((r.resolution, l1));
    }
    t
}

/// Runs the data file's runs (those `tested`, or all) and compares every value.
fn check_runs(name: &str, d: &Data, problem: Problem, all: bool) {
    for r in d.run.iter().filter(|r| all || r.tested) {
        let n = Some(r.resolution);
        let o = match d.geometry.as_deref() {
            None => problem.run(n),
            Some("rz") => problem.run_rz(n, problem.default_scheme()),
            Some("rings") => problem.run_rings(n, problem.default_scheme()),
            Some(g) => panic!("{name}: unknown geometry {g}"),
        }
        .unwrap();
        for (key, expected) in &r.values {
            let tolerance = d.tolerance[key];
            let got = o.get(key).unwrap_or_else(|| panic!("{name}: no key {key}"));
            assert!(
                (got - expected).abs() <= tolerance,
                "{name} at {}: {key} = {got}, the data file has {expected} (± {tolerance}): \
                 re-measure docs/verification/data/{name}.toml \
                 (docs/scripts/remeasure_verification.py)",
                r.resolution,
            );
        }
    }
}

fn check_page(name: &str, table: &str) {
    let page = std::fs::read_to_string(docs().join(format!("{name}.md"))).unwrap();
    assert!(
        page.contains(table),
        "docs/verification/{name}.md does not show its data file's table; it should read:\n{table}"
    );
}

/// The data files: data file name (and, unless the file names another `page`, the page
/// that shows its table), the problem, how the table is made. The runs marked `tested = false` in a data file are slow (seconds to
/// minutes in release: the HEL impact, the spinning disc, the contact with its 3-D
/// sphere, the tensile bar, the finer Sedov and Noh grids); the ignored test runs them. Their targets are also checked by
/// tests/solver.rs and tests/solid.rs.
type Table = fn(&Data) -> String;
const PAGES: [(&str, Problem, Table); 20] = [
    ("sod", Problem::Sod, riemann_table),
    ("toro123", Problem::Toro123, column_table),
    ("toro3", Problem::Toro3, column_table),
    ("noh_planar", Problem::NohPlanar, column_table),
    ("noh_cylindrical", Problem::NohCylindrical, column_table),
    ("noh_spherical", Problem::NohSpherical, column_table),
    ("noh_spherical_rz", Problem::NohSpherical, column_table),
    ("sedov_2d", Problem::Sedov2d, column_table),
    ("sedov_3d", Problem::Sedov3d, column_table),
    ("sedov_3d_rz", Problem::Sedov3d, column_table),
    ("elastic_bar", Problem::ElasticBar, column_table),
    ("hel_impact", Problem::HelImpact, column_table),
    ("spin", Problem::Spin, column_table),
    ("contact", Problem::Contact, column_table),
    ("tensile_bar", Problem::TensileBar, column_table),
    ("rings", Problem::Rings, column_table),
    ("taylor_rz", Problem::Taylor, column_table),
    ("taylor", Problem::Taylor, column_table),
    ("taylor_rings", Problem::Taylor, column_table),
    ("plate", Problem::Plate, column_table),
];

#[test]
fn every_page_shows_its_data_and_the_code_reproduces_the_tested_runs() {
    for (name, problem, table) in PAGES {
        check_problem(name, problem, table);
    }
}

/// Every page is in the index, and every data file here has its entry in PAGES.
#[test]
fn the_index_lists_every_page() {
    let index = std::fs::read_to_string(docs().join("README.md")).unwrap();
    for (name, _, _) in PAGES {
        let page = data(name).page.unwrap_or_else(|| name.to_string());
        assert!(
            index.contains(&format!("]({page}.md)")),
            "README.md lacks {page}"
        );
    }
    let files = std::fs::read_dir(docs().join("data")).unwrap().count();
    assert_eq!(files, PAGES.len(), "a data file without its entry in PAGES");
}

#[test]
#[ignore = "every run of every data file, the slow ones too: about 1.5 h in release; cargo test -p sph-impact --release --test verification_pages -- --ignored"]
fn every_resolution_of_the_data_files() {
    for (name, problem, _) in PAGES {
        check_runs(name, &data(name), problem, true);
    }
}
