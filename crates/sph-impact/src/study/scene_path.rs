//! A study's parameter paths: where in a scene a value is set.
//!
//! A path is the dotted path of a scene key (docs/scenes.md), with two additions:
//!
//! - `body.NAME` selects the `[[body]]` named NAME (`body[2]` selects by position, from 0);
//! - below a body's `material`, a built-in material given by name
//!   (`material = "basalt-study"`) becomes the inline material `{ base = "basalt-study" }`
//!   first, so that `body.target.material.damage.k` sets the Weibull k of the target's
//!   material and keeps the rest of it (docs/materials.md, `base`).
//!
//! An element of an array is `key[i]` (`body.projectile.velocity[2]`). Tables on the way
//! that the scene does not write are created; whether the key is one the scene takes is
//! decided by reading the scene afterwards, which names the key when it is not.

use toml::{Table, Value};

/// Sets `value` at `path` in the scene `scene`. `Err` says what in the path is wrong.
pub(crate) fn set(scene: &mut Table, path: &str, value: Value) -> Result<(), String> {
    let segments: Vec<&str> = path.split('.').collect();
    if path.is_empty() || segments.iter().any(|s| s.is_empty()) {
        return Err(format!("`{path}` is not a dotted path of scene keys"));
    }
    let mut table = scene;
    let mut k = 0;
    while k < segments.len() {
        let (key, index) = split_index(segments[k])?;
        let last = k + 1 == segments.len();
        if key == "body" && index.is_none() {
            // `body.NAME`: the body with that name.
            let Some(name) = segments.get(k + 1) else {
                return Err(
                    "`body` needs a body's name (`body.target.…`) or position (`body[1].…`)".into(),
                );
            };
            table = body_named(table, name)?;
            k += 2;
            if k == segments.len() {
                return Err(format!("`{path}` names a whole body, not one of its keys"));
            }
            continue;
        }
        if last {
            match index {
                None => {
                    table.insert(key.to_owned(), value);
                }
                Some(i) => {
                    let Some(Value::Array(items)) = table.get_mut(key) else {
                        return Err(format!("`{key}` is not an array in the scene"));
                    };
                    let n = items.len();
                    let Some(slot) = items.get_mut(i) else {
                        return Err(format!("`{key}` has {n} elements: no [{i}]"));
                    };
                    *slot = value;
                }
            }
            return Ok(());
        }
        table = match index {
            None => {
                // A body's material given by name becomes `{ base = NAME }`.
                if key == "material"
                    && let Some(Value::String(name)) = table.get(key)
                {
                    let mut inline = Table::new();
                    inline.insert("base".into(), Value::String(name.clone()));
                    table.insert(key.into(), Value::Table(inline));
                }
                let entry = table
                    .entry(key.to_owned())
                    .or_insert_with(|| Value::Table(Table::new()));
                match entry {
                    Value::Table(t) => t,
                    _ => return Err(format!("`{key}` is a value in the scene, not a table")),
                }
            }
            Some(i) => {
                let Some(Value::Array(items)) = table.get_mut(key) else {
                    return Err(format!("`{key}` is not an array in the scene"));
                };
                let n = items.len();
                match items.get_mut(i) {
                    Some(Value::Table(t)) => t,
                    Some(_) => return Err(format!("`{key}[{i}]` is not a table")),
                    None => return Err(format!("`{key}` has {n} elements: no [{i}]")),
                }
            }
        };
        k += 1;
    }
    Ok(())
}

/// `key` or `key[i]`.
fn split_index(segment: &str) -> Result<(&str, Option<usize>), String> {
    let Some(open) = segment.find('[') else {
        return Ok((segment, None));
    };
    let index = segment[open + 1..]
        .strip_suffix(']')
        .and_then(|i| i.parse().ok())
        .ok_or_else(|| format!("`{segment}`: an index is written `key[0]`"))?;
    Ok((&segment[..open], Some(index)))
}

/// The `[[body]]` table named `name`.
fn body_named<'a>(scene: &'a mut Table, name: &str) -> Result<&'a mut Table, String> {
    let Some(Value::Array(bodies)) = scene.get_mut("body") else {
        return Err("the scene has no `[[body]]`".into());
    };
    let names: Vec<String> = bodies
        .iter()
        .filter_map(|b| b.get("name").and_then(Value::as_str).map(str::to_owned))
        .collect();
    bodies
        .iter_mut()
        .filter_map(|b| match b {
            Value::Table(t) => Some(t),
            _ => None,
        })
        .find(|t| t.get("name").and_then(Value::as_str) == Some(name))
        .ok_or_else(|| {
            format!(
                "the scene has no body named `{name}` (its bodies: {})",
                names.join(", ")
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene() -> Table {
        toml::from_str(
            r#"
end_time = 1e-6
[[body]]
name = "projectile"
material = "aluminium-2024-jc"
velocity = [0.0, 0.0, -3900.0]
[[body]]
name = "target"
material = "basalt-study"
[solver]
n_target = 2.5
"#,
        )
        .unwrap()
    }

    #[test]
    fn a_top_level_and_a_nested_key_are_set_and_missing_tables_created() {
        let mut s = scene();
        set(&mut s, "end_time", Value::Float(2e-6)).unwrap();
        set(&mut s, "solver.n_target", Value::Float(3.0)).unwrap();
        set(&mut s, "solver.viscosity.alpha", Value::Float(1.5)).unwrap();
        assert_eq!(s["end_time"].as_float(), Some(2e-6));
        assert_eq!(s["solver"]["n_target"].as_float(), Some(3.0));
        assert_eq!(s["solver"]["viscosity"]["alpha"].as_float(), Some(1.5));
    }

    /// `body.NAME.material.…` turns a built-in name into `{ base = NAME }` and sets the
    /// key in it; the other body is untouched.
    #[test]
    fn a_material_key_of_a_named_body_extends_its_built_in_material() {
        let mut s = scene();
        set(&mut s, "body.target.material.damage.k", Value::Float(1e40)).unwrap();
        let bodies = s["body"].as_array().unwrap();
        let target = &bodies[1]["material"];
        assert_eq!(target["base"].as_str(), Some("basalt-study"));
        assert_eq!(target["damage"]["k"].as_float(), Some(1e40));
        assert_eq!(bodies[0]["material"].as_str(), Some("aluminium-2024-jc"));
    }

    #[test]
    fn an_array_element_and_a_body_by_position_are_set() {
        let mut s = scene();
        set(&mut s, "body.projectile.velocity[2]", Value::Float(-2300.0)).unwrap();
        set(&mut s, "body[1].name", Value::String("rock".into())).unwrap();
        let bodies = s["body"].as_array().unwrap();
        assert_eq!(bodies[0]["velocity"][2].as_float(), Some(-2300.0));
        assert_eq!(bodies[1]["name"].as_str(), Some("rock"));
    }

    #[test]
    fn bad_paths_say_what_is_wrong() {
        let cases = [
            ("", "not a dotted path"),
            ("solver..n_target", "not a dotted path"),
            (
                "body.asteroid.velocity",
                "no body named `asteroid` (its bodies: projectile, target)",
            ),
            ("body.target", "names a whole body"),
            ("body", "needs a body's name"),
            ("end_time.x", "is a value in the scene, not a table"),
            ("body.projectile.velocity[3]", "has 3 elements: no [3]"),
            ("solver.n_target[0]", "is not an array"),
            ("body.projectile.velocity[x]", "an index is written"),
        ];
        for (path, expected) in cases {
            let e = set(&mut scene(), path, Value::Float(1.0)).unwrap_err();
            assert!(e.contains(expected), "{path}: {e}");
        }
    }
}
