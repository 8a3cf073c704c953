//! The little XML the VTK writers need: attribute escaping (XML 1.0 §2.4, §3.3.3).

/// `text` with `& < > " '` replaced by entities, safe inside a double-quoted attribute.
pub fn escape_attribute(text: &str) -> String {
    let mut s = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            c => s.push(c),
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entities() {
        assert_eq!(
            escape_attribute(r#"a<b>&"c"'d'"#),
            "a&lt;b&gt;&amp;&quot;c&quot;&apos;d&apos;"
        );
        assert_eq!(escape_attribute("ρ (kg/m³)"), "ρ (kg/m³)");
    }
}
