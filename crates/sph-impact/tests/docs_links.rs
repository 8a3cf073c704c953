//! The documentation's cross-references resolve: every relative Markdown link in the
//! README and under docs/ names a file that exists (and, with `#anchor`, one of its
//! headings), and every citation of a section in the source, the examples and the docs
//! (`docs/FILE.md, "Heading"` or `docs/FILE.md §N`) names a heading of that file. A page
//! that is split or a heading that is renamed fails here with the citing file and line.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Files under `dir` (recursively) whose name ends in one of `exts`.
fn files(dir: &Path, exts: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().to_string();
        if path.is_dir() {
            if name != "target" && !name.starts_with('.') {
                files(&path, exts, out);
            }
        } else if exts.iter().any(|e| name.ends_with(e)) {
            out.push(path);
        }
    }
}

/// The headings of a Markdown file (text after the `#`s), skipping fenced code.
fn headings(text: &str) -> Vec<String> {
    let mut fenced = false;
    let mut out = Vec::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if !fenced && line.starts_with('#') {
            let h = line.trim_start_matches('#');
            if h.starts_with(' ') {
                out.push(h.trim().to_string());
            }
        }
    }
    out
}

/// GitHub's anchor for a heading: lower case, letters, digits, `-` and `_` kept, spaces
/// to `-`, everything else dropped; repeated headings get `-1`, `-2`, ….
fn anchors(headings: &[String]) -> BTreeSet<String> {
    let mut seen = BTreeSet::new();
    for h in headings {
        let base: String = h
            .to_lowercase()
            .chars()
            .filter_map(|c| match c {
                ' ' => Some('-'),
                c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
                _ => None,
            })
            .collect();
        let mut slug = base.clone();
        let mut k = 1;
        while seen.contains(&slug) {
            slug = format!("{base}-{k}");
            k += 1;
        }
        seen.insert(slug);
    }
    seen
}

/// `(target, line number)` of each inline link `[text](target)` outside code.
fn links(text: &str) -> Vec<(String, usize)> {
    let mut out = Vec::new();
    let mut fenced = false;
    for (n, line) in text.lines().enumerate() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            continue;
        }
        let mut rest = line;
        while let Some(i) = rest.find("](") {
            let after = &rest[i + 2..];
            let Some(j) = after.find(')') else { break };
            out.push((after[..j].to_string(), n + 1));
            rest = &after[j..];
        }
    }
    out
}

#[test]
fn every_relative_link_in_the_docs_resolves() {
    let root = root();
    let mut pages = vec![root.join("README.md")];
    files(&root.join("docs"), &[".md"], &mut pages);
    let mut broken = Vec::new();
    for page in &pages {
        let text = std::fs::read_to_string(page).unwrap();
        for (target, line) in links(&text) {
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let target = target.split_whitespace().next().unwrap_or("");
            let (file, anchor) = match target.split_once('#') {
                Some((f, a)) => (f, Some(a)),
                None => (target, None),
            };
            let file = if file.is_empty() {
                page.clone()
            } else {
                page.parent().unwrap().join(file)
            };
            let shown = page.strip_prefix(&root).unwrap().display();
            if !file.exists() {
                broken.push(format!("{shown}:{line}: no file {target}"));
                continue;
            }
            if let Some(anchor) = anchor {
                let text = std::fs::read_to_string(&file).unwrap_or_default();
                if !anchors(&headings(&text)).contains(anchor) {
                    broken.push(format!("{shown}:{line}: no heading #{anchor} in {target}"));
                }
            }
        }
    }
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

/// `docs/FILE.md, "Heading"` and `docs/FILE.md §N`: the cited file and the heading.
fn citations(text: &str) -> Vec<(String, String, usize)> {
    let mut out = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(i) = rest.find("docs/") {
            let after = &rest[i..];
            let Some(end) = after.find(".md") else { break };
            let file = &after[..end + 3];
            rest = &after[end + 3..];
            // `docs/FILE.md` is this file's own placeholder, not a citation.
            if file.contains(char::is_whitespace) || file.contains("FILE") {
                continue;
            }
            let tail = rest.strip_prefix(',').unwrap_or(rest);
            if let Some(q) = tail.strip_prefix(" \"") {
                if let Some(close) = q.find('"') {
                    out.push((file.to_string(), q[..close].to_string(), n + 1));
                }
            } else if let Some(s) = tail.strip_prefix(" §") {
                let num: String = s
                    .chars()
                    .take_while(|c| c.is_ascii_digit() || *c == '.')
                    .collect();
                let num = num.trim_end_matches('.');
                if !num.is_empty() {
                    out.push((file.to_string(), format!("§{num}"), n + 1));
                }
            }
        }
    }
    out
}

#[test]
fn every_cited_section_exists() {
    let root = root();
    let mut sources = vec![root.join("README.md")];
    for dir in ["crates", "examples", "benches", "docs"] {
        files(
            &root.join(dir),
            &[".rs", ".md", ".toml", ".py"],
            &mut sources,
        );
    }
    let mut broken = Vec::new();
    for source in &sources {
        // Binary inputs (fuzz corpora) are not text and cite nothing.
        let Ok(text) = std::fs::read_to_string(source) else {
            continue;
        };
        for (file, section, line) in citations(&text) {
            let shown = source.strip_prefix(&root).unwrap().display();
            let Ok(doc) = std::fs::read_to_string(root.join(&file)) else {
                broken.push(format!("{shown}:{line}: no file {file}"));
                continue;
            };
            let hs = headings(&doc);
            let found = if let Some(num) = section.strip_prefix('§') {
                hs.iter().any(|h| {
                    h.strip_prefix(num)
                        .is_some_and(|r| r.starts_with(' ') || r.starts_with(". "))
                })
            } else {
                let want = section.to_lowercase();
                hs.iter().any(|h| h.to_lowercase().starts_with(&want))
            };
            if !found {
                broken.push(format!("{shown}:{line}: {file} has no section {section}"));
            }
        }
    }
    assert!(
        broken.is_empty(),
        "citations of missing sections:\n{}",
        broken.join("\n")
    );
}

#[test]
fn the_anchor_rule_matches_github() {
    let hs: Vec<String> = [
        "The flaws' draw: seed-to-seed scatter",
        "β in time",
        "Noh (γ = 5/3)",
        "A",
        "A",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let a = anchors(&hs);
    assert!(a.contains("the-flaws-draw-seed-to-seed-scatter"));
    assert!(a.contains("β-in-time"));
    assert!(a.contains("noh-γ--53"));
    assert!(a.contains("a") && a.contains("a-1"));
}
