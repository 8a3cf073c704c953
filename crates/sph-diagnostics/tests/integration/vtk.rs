//! VTU and PVD writers: files are written, read back, checked for well-formed structure
//! (balanced tags, no XML crate) and their base64 arrays decoded to the values written.

use base64::Engine;
use base64::engine::general_purpose::STANDARD;
use proptest::prelude::*;
use sph_diagnostics::pvtu::{write_pvtu, write_pvtu_to};
use sph_diagnostics::{Pvd, VtuWriter};
use std::path::PathBuf;

/// A fresh directory for this test's files.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sph-diag-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Checks that every `<tag …>` is closed by a matching `</tag>` in order (self-closing
/// tags and the `<?xml ?>` declaration aside), and that attribute values are quoted
/// pairs. Returns the sequence of opened element names.
fn check_structure(xml: &str) -> Vec<String> {
    assert!(xml.starts_with("<?xml version=\"1.0\"?>"));
    let mut stack: Vec<String> = Vec::new();
    let mut opened = Vec::new();
    let mut rest = xml;
    while let Some(start) = rest.find('<') {
        let end = rest[start..].find('>').expect("unterminated tag") + start;
        let tag = &rest[start + 1..end];
        rest = &rest[end + 1..];
        assert!(!tag.contains('<'), "nested '<' in {tag}");
        assert_eq!(
            tag.matches('"').count() % 2,
            0,
            "unbalanced quotes in {tag}"
        );
        if tag.starts_with('?') {
            continue;
        }
        if let Some(name) = tag.strip_prefix('/') {
            assert_eq!(stack.pop().as_deref(), Some(name), "mismatched </{name}>");
        } else {
            let name = tag.split_whitespace().next().unwrap().trim_end_matches('/');
            opened.push(name.to_string());
            if !tag.ends_with('/') {
                stack.push(name.to_string());
            }
        }
    }
    assert!(stack.is_empty(), "unclosed {stack:?}");
    opened
}

/// The attributes and decoded bytes (header removed, checked) of the DataArray named
/// `name`.
fn array(xml: &str, name: &str) -> (String, Vec<u8>) {
    let key = format!("Name=\"{name}\"");
    let at = xml.find(&key).unwrap_or_else(|| panic!("no array {name}"));
    let open = xml[..at].rfind('<').unwrap();
    let close = at + xml[at..].find('>').unwrap();
    let end = close + xml[close..].find("</DataArray>").unwrap();
    let bytes = STANDARD.decode(xml[close + 1..end].trim()).unwrap();
    let (header, data) = bytes.split_at(8);
    assert_eq!(
        u64::from_le_bytes(header.try_into().unwrap()) as usize,
        data.len()
    );
    (xml[open..close].to_string(), data.to_vec())
}

fn f64s(b: &[u8]) -> Vec<f64> {
    b.chunks_exact(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect()
}

#[test]
fn vtu_round_trips_every_array_type() {
    let x = [[0.0, 1.0, 2.0], [-1e-3, 5e300, f64::MIN_POSITIVE]];
    let rho = [2876.0, 2785.5];
    let v = [[1.0, -2.0, 3.0], [0.0, 0.0, -3900.0]];
    let s = [[1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0], [-1.0; 9]];
    let label = [7, -3];
    let body = [0u16, 65535];
    let id = [u64::MAX, 3];
    let mut w = VtuWriter::new(2);
    w.points(&x)
        .scalar("density", &rho)
        .vector("velocity", &v)
        .tensor("stress", &s)
        .int("fragment", &label)
        .uint16("body <id>", &body)
        .uint64("id", &id);
    let dir = scratch("vtu");
    let path = dir.join("step.vtu");
    w.write(&path).unwrap();
    let xml = std::fs::read_to_string(&path).unwrap();

    let opened = check_structure(&xml);
    assert_eq!(
        &opened[..4],
        ["VTKFile", "UnstructuredGrid", "Piece", "PointData"]
    );
    assert!(xml.contains("header_type=\"UInt64\""));
    assert!(xml.contains("<Piece NumberOfPoints=\"2\" NumberOfCells=\"2\">"));

    let (attrs, d) = array(&xml, "Points");
    assert!(attrs.contains("type=\"Float64\"") && attrs.contains("NumberOfComponents=\"3\""));
    assert_eq!(f64s(&d), x.concat());
    assert_eq!(f64s(&array(&xml, "density").1), rho);
    assert_eq!(f64s(&array(&xml, "velocity").1), v.concat());
    let (attrs, d) = array(&xml, "stress");
    assert!(attrs.contains("NumberOfComponents=\"9\""));
    assert_eq!(f64s(&d), s.concat());
    let (attrs, d) = array(&xml, "fragment");
    assert!(attrs.contains("type=\"Int32\""));
    let ints: Vec<i32> = d
        .chunks_exact(4)
        .map(|c| i32::from_le_bytes(c.try_into().unwrap()))
        .collect();
    assert_eq!(ints, label);
    let (attrs, d) = array(&xml, "body &lt;id&gt;");
    assert!(attrs.contains("type=\"UInt16\""));
    assert_eq!(d, [0, 0, 255, 255]);
    let (attrs, d) = array(&xml, "id");
    assert!(attrs.contains("type=\"UInt64\""));
    let u64s: Vec<u64> = d
        .chunks_exact(8)
        .map(|c| u64::from_le_bytes(c.try_into().unwrap()))
        .collect();
    assert_eq!(u64s, id);
    let ids = |b: Vec<u8>| -> Vec<i64> {
        b.chunks_exact(8)
            .map(|c| i64::from_le_bytes(c.try_into().unwrap()))
            .collect()
    };
    assert_eq!(ids(array(&xml, "connectivity").1), [0, 1]);
    assert_eq!(ids(array(&xml, "offsets").1), [1, 2]);
    assert_eq!(array(&xml, "types").1, [1, 1]);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn vtu_mistakes_are_invalid_input_naming_the_array() {
    let x = [[0.0; 3]; 3];
    let short = [1.0, 2.0];
    let mut w = VtuWriter::new(3);
    w.points(&x).scalar("density", &short);
    let err = w.write_to(&mut Vec::new()).unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
    assert!(err.to_string().contains("density"), "{err}");
    let rho = [1.0; 3];
    let mut twice = VtuWriter::new(3);
    twice.points(&x).scalar("rho", &rho).scalar("rho", &rho);
    assert!(twice.write_to(&mut Vec::new()).is_err());
    let no_points = VtuWriter::new(0);
    assert!(no_points.write_to(&mut Vec::new()).is_err());
    let mut empty = VtuWriter::new(0);
    empty.points(&[]);
    let mut out = Vec::new();
    empty.write_to(&mut out).unwrap();
    check_structure(&String::from_utf8(out).unwrap());
}

#[test]
fn pvd_lists_the_snapshots() {
    let mut pvd = Pvd::new();
    pvd.push(0.0, "run/step_0000.vtu")
        .push(2.5e-6, "run/step_0001.vtu");
    assert_eq!(pvd.len(), 2);
    let dir = scratch("pvd");
    let path = dir.join("run.pvd");
    pvd.write(&path).unwrap();
    let xml = std::fs::read_to_string(&path).unwrap();
    assert_eq!(
        check_structure(&xml),
        ["VTKFile", "Collection", "DataSet", "DataSet"]
    );
    assert!(xml.contains("timestep=\"2.5e-6\""));
    assert!(xml.contains("file=\"run/step_0001.vtu\""));
    let times: Vec<f64> = xml
        .split("timestep=\"")
        .skip(1)
        .map(|s| s[..s.find('"').unwrap()].parse().unwrap())
        .collect();
    assert_eq!(times, [0.0, 2.5e-6]);
    let mut bad = Pvd::new();
    bad.push(f64::NAN, "x.vtu");
    assert!(bad.write_to(&mut Vec::new()).is_err());
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn pieces_hold_the_whole_in_order_and_the_pvtu_declares_and_lists_them() {
    let n = 7;
    let x: Vec<[f64; 3]> = (0..n).map(|i| [i as f64, -(i as f64), 0.5]).collect();
    let rho: Vec<f64> = (0..n).map(|i| 2700.0 + i as f64).collect();
    let s: Vec<[f64; 9]> = (0..n).map(|i| [i as f64; 9]).collect();
    let body: Vec<u16> = (0..n as u16).collect();
    let mut w = VtuWriter::new(n);
    w.points(&x)
        .scalar("density", &rho)
        .tensor("stress", &s)
        .uint16("material", &body);
    let mut whole = Vec::new();
    w.write_to(&mut whole).unwrap();
    let whole = String::from_utf8(whole).unwrap();
    // Three pieces, one of them empty: their arrays joined are the whole's.
    let cuts = [0..3, 3..3, 3..7];
    let dir = scratch("pvtu");
    let mut joined: Vec<Vec<u8>> = vec![Vec::new(); 4];
    for (k, rows) in cuts.iter().enumerate() {
        let piece = w.piece(rows.clone());
        piece.write(dir.join(format!("p_{k}.vtu"))).unwrap();
        let xml = std::fs::read_to_string(dir.join(format!("p_{k}.vtu"))).unwrap();
        check_structure(&xml);
        let m = rows.len();
        assert!(xml.contains(&format!("NumberOfPoints=\"{m}\" NumberOfCells=\"{m}\"")));
        for (j, name) in ["Points", "density", "stress", "material"]
            .iter()
            .enumerate()
        {
            joined[j].extend(array(&xml, name).1);
        }
    }
    for (j, name) in ["Points", "density", "stress", "material"]
        .iter()
        .enumerate()
    {
        assert_eq!(joined[j], array(&whole, name).1, "{name}");
    }
    let sources = ["p_0.vtu", "p_1.vtu", "p_2.vtu"];
    write_pvtu(dir.join("all.pvtu"), &w, &sources).unwrap();
    let xml = std::fs::read_to_string(dir.join("all.pvtu")).unwrap();
    assert_eq!(
        check_structure(&xml),
        [
            "VTKFile",
            "PUnstructuredGrid",
            "PPointData",
            "PDataArray",
            "PDataArray",
            "PDataArray",
            "PPoints",
            "PDataArray",
            "Piece",
            "Piece",
            "Piece"
        ]
    );
    assert!(xml.contains("type=\"PUnstructuredGrid\""));
    assert!(
        xml.contains("<PDataArray type=\"Float64\" Name=\"stress\" NumberOfComponents=\"9\"/>")
    );
    assert!(
        xml.contains("<PDataArray type=\"UInt16\" Name=\"material\" NumberOfComponents=\"1\"/>")
    );
    let listed: Vec<&str> = xml
        .split("Source=\"")
        .skip(1)
        .map(|s| &s[..s.find('"').unwrap()])
        .collect();
    assert_eq!(listed, sources);
    // A piece's writer declares the same arrays as the whole's.
    let mut from_piece = Vec::new();
    write_pvtu_to(&mut from_piece, &w.piece(3..3), &sources).unwrap();
    assert_eq!(String::from_utf8(from_piece).unwrap(), xml);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn piece_and_pvtu_mistakes_are_invalid_input() {
    let x = [[0.0; 3]; 3];
    let rho = [1.0; 3];
    let mut w = VtuWriter::new(3);
    w.points(&x).scalar("density", &rho);
    let err = w.piece(2..4).write_to(&mut Vec::new()).unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
    assert!(err.to_string().contains("2..4"), "{err}");
    let none: [&str; 0] = [];
    let err = write_pvtu_to(&mut Vec::new(), &w, &none).unwrap_err();
    assert_eq!(err.kind(), std::io::ErrorKind::InvalidInput);
    assert!(write_pvtu_to(&mut Vec::new(), &w, &["a.vtu", ""]).is_err());
    // The whole's own mistake is the piece's and the pvtu's.
    let short = [1.0];
    let mut bad = VtuWriter::new(3);
    bad.points(&x).scalar("density", &short);
    assert!(bad.piece(0..1).write_to(&mut Vec::new()).is_err());
    assert!(write_pvtu_to(&mut Vec::new(), &bad, &["a.vtu"]).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn random_arrays_round_trip(
        pts in prop::collection::vec(prop::array::uniform3(any::<f64>()), 0..40),
    ) {
        let n = pts.len();
        let ints: Vec<i32> = (0..n as i32).map(|i| i * 7919 - 100).collect();
        let mut w = VtuWriter::new(n);
        w.points(&pts).vector("v", &pts).int("i", &ints);
        let mut out = Vec::new();
        w.write_to(&mut out).unwrap();
        let xml = String::from_utf8(out).unwrap();
        check_structure(&xml);
        let back = f64s(&array(&xml, "v").1);
        // Bit-exact, NaN included.
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        prop_assert_eq!(bits(&back), bits(&pts.concat()));
        prop_assert_eq!(array(&xml, "i").1.len(), 4 * n);
    }
}
