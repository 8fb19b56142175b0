//! The container's metadata (`meta.yml`, or `index.json`: JSON is YAML)
//! as a small tree, built from the events of the `yaml-rust2` parser with
//! the bounds of untrusted input: a nesting depth of [`MAX_DEPTH`], no
//! aliases (a billion-laughs document is refused, not expanded), tags
//! such as `!!python/tuple` read as the node they tag (PyYAML's
//! `FullLoader`, which SurfaceTopography uses, makes a tuple a sequence).
//!
//! Own tree rather than `yaml-rust2`'s loader: its `Yaml` has no depth
//! bound (a deep document would overflow the stack when dropped) and
//! expands aliases.

use yaml_rust2::parser::{Event, Parser};
use yaml_rust2::scanner::TScalarStyle;

/// The deepest nesting of sequences and mappings the metadata may have.
pub(crate) const MAX_DEPTH: usize = 64;

/// A node of the metadata.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Node {
    /// A scalar: its text and whether it was plain (unquoted: may be a
    /// number, a boolean or null).
    Scalar(String, bool),
    /// A sequence.
    Seq(Vec<Node>),
    /// A mapping, in the document's order (keys as their text).
    Map(Vec<(String, Node)>),
}

impl Node {
    /// The value of `key` in a mapping.
    pub(crate) fn get(&self, key: &str) -> Option<&Node> {
        match self {
            Node::Map(entries) => entries.iter().find(|(k, _)| k == key).map(|(_, v)| v),
            _ => None,
        }
    }

    /// A scalar's text (`None` for null and non-scalars).
    pub(crate) fn text(&self) -> Option<&str> {
        match self {
            Node::Scalar(s, plain) if !(*plain && is_null(s)) => Some(s),
            _ => None,
        }
    }

    /// Whether the node is null (`~`, `null`, empty plain scalar).
    pub(crate) fn is_null(&self) -> bool {
        matches!(self, Node::Scalar(s, true) if is_null(s))
    }

    /// A plain scalar read as a number (YAML 1.1/1.2 floats and integers,
    /// as PyYAML reads them).
    pub(crate) fn number(&self) -> Option<f64> {
        match self {
            Node::Scalar(s, true) => {
                let t = s.trim().replace('_', "");
                match t.to_ascii_lowercase().as_str() {
                    ".inf" | "+.inf" => Some(f64::INFINITY),
                    "-.inf" => Some(f64::NEG_INFINITY),
                    ".nan" => Some(f64::NAN),
                    _ => t.parse::<f64>().ok(),
                }
            }
            _ => None,
        }
    }

    /// A plain scalar read as a boolean.
    pub(crate) fn boolean(&self) -> Option<bool> {
        match self {
            Node::Scalar(s, true) => match s.to_ascii_lowercase().as_str() {
                "true" | "yes" | "on" => Some(true),
                "false" | "no" | "off" => Some(false),
                _ => None,
            },
            _ => None,
        }
    }

    /// A sequence's items.
    pub(crate) fn items(&self) -> Option<&[Node]> {
        match self {
            Node::Seq(items) => Some(items),
            _ => None,
        }
    }
}

fn is_null(s: &str) -> bool {
    matches!(s, "" | "~" | "null" | "Null" | "NULL")
}

/// Parses `text` (one document) into a tree; an error says what is wrong
/// and where (line).
pub(crate) fn parse(text: &str) -> Result<Node, String> {
    let mut parser = Parser::new_from_str(text);
    // Open containers: a sequence's items, or a mapping's entries with the
    // key waiting for its value.
    enum Open {
        Seq(Vec<Node>),
        Map(Vec<(String, Node)>, Option<String>),
    }
    let mut stack: Vec<Open> = Vec::new();
    let mut root: Option<Node> = None;
    loop {
        let (event, mark) = parser.next_token().map_err(|e| {
            // The scanner's own bound on flow nesting (it reads ahead of
            // the events) says the same as ours.
            if e.info().contains("recursion limit") {
                format!("line {}: nested deeper than {MAX_DEPTH} levels", e.marker().line())
            } else {
                e.to_string()
            }
        })?;
        let node = match event {
            Event::StreamEnd => break,
            Event::Nothing | Event::StreamStart | Event::DocumentStart | Event::DocumentEnd => continue,
            Event::Alias(_) => {
                return Err(format!("line {}: aliases (*name) are not accepted", mark.line()));
            }
            Event::Scalar(text, style, _, _) => Node::Scalar(text, style == TScalarStyle::Plain),
            Event::SequenceStart(..) | Event::MappingStart(..) => {
                if stack.len() >= MAX_DEPTH {
                    return Err(format!("line {}: nested deeper than {MAX_DEPTH} levels", mark.line()));
                }
                stack.push(match event {
                    Event::SequenceStart(..) => Open::Seq(Vec::new()),
                    _ => Open::Map(Vec::new(), None),
                });
                continue;
            }
            Event::SequenceEnd | Event::MappingEnd => match stack.pop() {
                Some(Open::Seq(items)) => Node::Seq(items),
                Some(Open::Map(entries, _)) => Node::Map(entries),
                None => return Err("unbalanced document".into()),
            },
        };
        match stack.last_mut() {
            None => {
                if root.is_some() {
                    return Err("more than one document".into());
                }
                root = Some(node);
            }
            Some(Open::Seq(items)) => items.push(node),
            Some(Open::Map(entries, key)) => match key.take() {
                None => match node {
                    Node::Scalar(k, _) => *key = Some(k),
                    _ => return Err(format!("line {}: a mapping key that is not a scalar", mark.line())),
                },
                Some(k) => entries.push((k, node)),
            },
        }
    }
    root.ok_or_else(|| "an empty document".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tags_are_read_as_the_node_they_tag() {
        let doc = "size: !!python/tuple\n- 1.5\n- 2\nunit: nm\nq: 'x'\nn: ~\n";
        let n = parse(doc).unwrap();
        let size: Vec<f64> = n
            .get("size")
            .unwrap()
            .items()
            .unwrap()
            .iter()
            .map(|v| v.number().unwrap())
            .collect();
        assert_eq!(size, [1.5, 2.0]);
        assert_eq!(n.get("unit").unwrap().text(), Some("nm"));
        assert_eq!(n.get("q").unwrap().number(), None);
        assert!(n.get("n").unwrap().is_null());
    }

    #[test]
    fn deep_documents_and_aliases_are_refused() {
        let deep = "[".repeat(MAX_DEPTH + 1) + &"]".repeat(MAX_DEPTH + 1);
        assert!(parse(&deep).unwrap_err().contains("nested deeper"));
        let fine = "[".repeat(MAX_DEPTH) + &"]".repeat(MAX_DEPTH);
        assert!(parse(&fine).is_ok());
        let deep = "[".repeat(1_000_000);
        assert!(parse(&deep).is_err());
        assert!(parse("a: &x [1]\nb: *x\n").unwrap_err().contains("aliases"));
        assert!(parse("{\"a\": [1, 2]}").is_ok());
    }
}
