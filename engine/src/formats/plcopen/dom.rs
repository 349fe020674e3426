//! A small element tree over quick-xml events: names without namespace
//! prefixes, attributes, text, and the line each element starts on.

use quick_xml::events::{BytesStart, Event};
use quick_xml::Reader;

use std::fmt;

use crate::error::Located;
use crate::limits::{MAX_INPUT_BYTES, MAX_XML_ATTRIBUTES, MAX_XML_DEPTH};
use std::collections::HashSet;

/// Why the text is not XML the reader takes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum XmlError {
    /// Larger than [`MAX_INPUT_BYTES`] (its size).
    TooLarge(usize),
    /// The XML parser's words.
    NotWellFormed(String),
    /// An attribute that does not parse (element, parser's words).
    BadAttribute(String, String),
    /// Text that does not unescape (parser's words).
    BadText(String),
    /// An end tag with no start.
    EndWithoutStart,
    /// An element never closed (its name).
    NeverClosed(String),
    /// No element at all.
    Empty,
    /// Elements nested past [`MAX_XML_DEPTH`].
    TooDeep,
    /// An element with more than [`MAX_XML_ATTRIBUTES`] attributes (its
    /// name).
    TooManyAttributes(String),
    /// An attribute written twice on one element (element, attribute).
    DuplicateAttribute(String, String),
    /// A second element at the top (its name).
    SecondRoot(String),
}

impl fmt::Display for XmlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            XmlError::TooLarge(n) => write!(
                f,
                "the file is {n} bytes, more than the {MAX_INPUT_BYTES} a PLCopen file may have (docs/limits.md)"
            ),
            XmlError::NotWellFormed(e) => write!(f, "not well-formed XML: {e}"),
            XmlError::BadAttribute(el, e) => write!(f, "bad attribute in <{el}>: {e}"),
            XmlError::BadText(e) => write!(f, "bad text: {e}"),
            XmlError::EndWithoutStart => f.write_str("an end tag with no start"),
            XmlError::NeverClosed(el) => write!(f, "<{el}> is never closed"),
            XmlError::Empty => f.write_str("no XML element found"),
            XmlError::TooDeep => write!(
                f,
                "elements nest more than {MAX_XML_DEPTH} deep here (docs/limits.md)"
            ),
            XmlError::TooManyAttributes(el) => write!(
                f,
                "<{el}> has more than {MAX_XML_ATTRIBUTES} attributes (docs/limits.md)"
            ),
            XmlError::DuplicateAttribute(el, a) => {
                write!(f, "bad attribute in <{el}>: `{a}` is written twice")
            }
            XmlError::SecondRoot(el) => write!(
                f,
                "a second root element <{el}>: an XML file holds one element, the project"
            ),
        }
    }
}

impl std::error::Error for XmlError {}

/// One XML element.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Node {
    /// The local name (`contact`, `xhtml:p` → `p`).
    pub name: String,
    /// Attributes by local name, in document order.
    pub attrs: Vec<(String, String)>,
    /// Child elements.
    pub children: Vec<Node>,
    /// The text directly inside (trimmed, CDATA included).
    pub text: String,
    /// The 1-based line of the start tag.
    pub line: usize,
}

impl Node {
    /// An attribute's value.
    pub fn attr(&self, name: &str) -> Option<&str> {
        self.attrs
            .iter()
            .find(|(k, _)| k == name)
            .map(|(_, v)| v.as_str())
    }

    /// The first child called `name`.
    pub fn child(&self, name: &str) -> Option<&Node> {
        self.children.iter().find(|c| c.name == name)
    }

    /// Every child called `name`.
    pub fn all<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Node> + 'a {
        self.children.iter().filter(move |c| c.name == name)
    }

    /// Every descendant called `name`, depth first.
    pub fn descendants<'a>(&'a self, name: &str, out: &mut Vec<&'a Node>) {
        for c in &self.children {
            if c.name == name {
                out.push(c);
            }
            c.descendants(name, out);
        }
    }

    /// All the text inside, children included.
    pub fn deep_text(&self) -> String {
        let mut s = self.text.clone();
        for c in &self.children {
            let t = c.deep_text();
            if !t.is_empty() {
                if !s.is_empty() {
                    s.push(' ');
                }
                s.push_str(&t);
            }
        }
        s
    }
}

fn line_at(text: &[u8], offset: u64) -> usize {
    let end = usize::try_from(offset)
        .unwrap_or(usize::MAX)
        .min(text.len());
    text[..end].iter().filter(|&&b| b == b'\n').count() + 1
}

/// Line numbers for offsets that only grow, counted incrementally (a
/// count from the start each time would make parsing quadratic).
struct Lines<'a> {
    text: &'a [u8],
    offset: usize,
    line: usize,
}

impl Lines<'_> {
    fn at(&mut self, offset: usize) -> usize {
        let offset = offset.min(self.text.len());
        if offset < self.offset {
            return line_at(self.text, offset as u64);
        }
        self.line += self.text[self.offset..offset]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        self.offset = offset;
        self.line
    }
}

/// The element `e` starts, its attributes read in linear time: quick-xml's
/// own check for a name written twice compares each with every one
/// before it (200 000 attributes took over 15 s), so a set of the names
/// seen does it, and an element past [`MAX_XML_ATTRIBUTES`] is refused
/// before the rest are read.
fn start(e: &BytesStart, line: usize) -> Result<Node, XmlError> {
    let name = String::from_utf8_lossy(e.local_name().as_ref()).into_owned();
    let mut attrs = Vec::new();
    let mut seen: HashSet<Vec<u8>> = HashSet::new();
    for a in e.attributes().with_checks(false) {
        let a = a.map_err(|err| XmlError::BadAttribute(name.clone(), err.to_string()))?;
        if attrs.len() == MAX_XML_ATTRIBUTES {
            return Err(XmlError::TooManyAttributes(name));
        }
        if !seen.insert(a.key.as_ref().to_vec()) {
            let key = String::from_utf8_lossy(a.key.as_ref()).into_owned();
            return Err(XmlError::DuplicateAttribute(name, key));
        }
        let key = String::from_utf8_lossy(a.key.local_name().as_ref()).into_owned();
        let value = a
            .unescape_value()
            .map_err(|err| XmlError::BadAttribute(name.clone(), err.to_string()))?
            .into_owned();
        // `xmlns` and `xmlns:x` both keep their name, so the namespace is visible.
        let key = if a.key.as_ref() == b"xmlns" {
            "xmlns".to_string()
        } else {
            key
        };
        attrs.push((key, value));
    }
    Ok(Node {
        name,
        attrs,
        line,
        ..Node::default()
    })
}

/// Refuses an element that starts after the root closed (XML has one
/// root; the second was ignored).
fn second_root(root: &Option<Node>, e: &BytesStart, line: usize) -> Result<(), Located<XmlError>> {
    if root.is_none() {
        return Ok(());
    }
    let name = String::from_utf8_lossy(e.local_name().as_ref()).into_owned();
    Err(Located::new(line, XmlError::SecondRoot(name)))
}

thread_local! {
    /// How many texts [`parse`] has read on this thread.
    static PARSED: std::cell::Cell<u64> = const { std::cell::Cell::new(0) };
}

/// How many XML texts this thread has parsed so far: a file is read into
/// a [`super::Document`] once and asked everything else, and the files
/// worker's tests hold it to that by counting.
pub fn parsed_count() -> u64 {
    PARSED.with(std::cell::Cell::get)
}

/// Parses `text` into its root element; errors name their line. Nesting
/// past [`MAX_XML_DEPTH`] and text past [`MAX_INPUT_BYTES`] are refused
/// before they are built, so every walk over the tree is shallow.
pub fn parse(text: &str) -> Result<Node, Located<XmlError>> {
    PARSED.with(|n| n.set(n.get().saturating_add(1)));
    tree(text)
}

/// [`parse`]'s work, uncounted.
fn tree(text: &str) -> Result<Node, Located<XmlError>> {
    if text.len() > MAX_INPUT_BYTES {
        return Err(Located::new(1, XmlError::TooLarge(text.len())));
    }
    let mut reader = Reader::from_str(text);
    reader.config_mut().trim_text(true);
    let mut stack: Vec<Node> = Vec::new();
    let mut root: Option<Node> = None;
    let mut lines = Lines {
        text: text.as_bytes(),
        offset: 0,
        line: 1,
    };
    loop {
        // The event starts at the first non-blank byte after the last one.
        let at = usize::try_from(reader.buffer_position()).unwrap_or(usize::MAX);
        let skip = text
            .get(at..)
            .map_or(0, |rest| rest.len() - rest.trim_start().len());
        let line = lines.at(at.saturating_add(skip));
        let event = reader.read_event().map_err(|e| {
            Located::new(
                line_at(text.as_bytes(), reader.error_position()),
                XmlError::NotWellFormed(e.to_string()),
            )
        })?;
        match event {
            Event::Start(e) => {
                if stack.is_empty() {
                    second_root(&root, &e, line)?;
                }
                if stack.len() >= MAX_XML_DEPTH {
                    return Err(Located::new(line, XmlError::TooDeep));
                }
                stack.push(start(&e, line).map_err(|m| Located::new(line, m))?)
            }
            Event::Empty(e) => {
                if stack.is_empty() {
                    second_root(&root, &e, line)?;
                }
                let node = start(&e, line).map_err(|m| Located::new(line, m))?;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(node),
                    None => root = Some(node),
                }
            }
            Event::End(_) => {
                let node = stack
                    .pop()
                    .ok_or_else(|| Located::new(line, XmlError::EndWithoutStart))?;
                match stack.last_mut() {
                    Some(parent) => parent.children.push(node),
                    None => root = Some(node),
                }
            }
            Event::Text(t) => {
                if let Some(n) = stack.last_mut() {
                    let s = t
                        .unescape()
                        .map_err(|e| Located::new(line, XmlError::BadText(e.to_string())))?;
                    n.text.push_str(s.trim());
                }
            }
            Event::CData(c) => {
                if let Some(n) = stack.last_mut() {
                    n.text.push_str(String::from_utf8_lossy(&c).trim());
                }
            }
            Event::Eof => break,
            _ => {}
        }
    }
    if !stack.is_empty() {
        return Err(Located::new(
            line_at(text.as_bytes(), text.len() as u64),
            XmlError::NeverClosed(stack[stack.len() - 1].name.clone()),
        ));
    }
    root.ok_or_else(|| Located::new(1, XmlError::Empty))
}
