//! The XML reader (item 9's second root, item 10's attributes).

use engine::formats::plcopen::Document;
use std::time::{Duration, Instant};

use engine::formats::plcopen::dom;

use super::*;

/// Item 10: 200 000 attributes on one element took over 15 s (each
/// attribute's name was compared with every one before it); now the
/// element is refused at its line as soon as it passes the limit.
#[test]
fn two_hundred_thousand_attributes_are_refused_at_their_line_at_once() {
    let attrs: String = (0..200_000).map(|i| format!(" a{i}=\"\"")).collect();
    let xml = format!("<project>\n<types/>\n<x{attrs}/>\n</project>");
    let started = Instant::now();
    let error = refused(dom::parse(&xml), "too many attributes");
    assert!(
        started.elapsed() < Duration::from_secs(3),
        "{:?}",
        started.elapsed()
    );
    assert_eq!(error.line, 3);
    assert_eq!(
        error.error.to_string(),
        "<x> has more than 256 attributes (docs/limits.md)"
    );
    // The importers say it at the same line.
    let errors = Document::read(&xml)
        .and_then(|document| document.import(None, None, None))
        .map(|i| i.ladder)
        .expect_err("refused");
    assert_eq!(errors[0].line, 3, "{errors:?}");
}

/// Item 10: the limit is exact: 256 attributes on an element are read
/// (thousands of such elements quickly), 257 are refused at the line.
#[test]
fn the_attribute_limit_is_exact() {
    let attrs = |n: usize| -> String { (0..n).map(|i| format!(" attribute{i}=\"v\"")).collect() };
    let element = format!("<x{}/>\n", attrs(256));
    let xml = format!("<project>\n{}</project>", element.repeat(3_000));
    let started = Instant::now();
    let root = dom::parse(&xml).expect("256 attributes are allowed");
    assert!(
        started.elapsed() < Duration::from_secs(20),
        "{:?}",
        started.elapsed()
    );
    assert_eq!(root.children.len(), 3_000);
    assert_eq!(root.children[2_999].attr("attribute255"), Some("v"));
    let xml = format!("<project>\n{element}<x{}/>\n</project>", attrs(257));
    let error = refused(dom::parse(&xml), "257 attributes");
    assert_eq!(error.line, 3);
}

/// Item 10: an attribute written twice is still not XML (it was found by
/// the quadratic check; now by a set of the names seen).
#[test]
fn an_attribute_written_twice_is_refused_at_its_line() {
    let error = refused(
        dom::parse("<project>\n<x a=\"1\" b=\"2\" a=\"3\"/>\n</project>"),
        "twice",
    );
    assert_eq!(error.line, 2);
    assert!(
        error.error.to_string().contains("`a` is written twice"),
        "{}",
        error.error
    );
}

/// Item 9: a second root element was ignored; XML has one.
#[test]
fn a_second_root_element_is_refused_at_its_line() {
    let xml = "<?xml version=\"1.0\"?>\n<project>\n</project>\n<project>\n<types/>\n</project>\n";
    let error = refused(dom::parse(xml), "two roots");
    assert_eq!(error.line, 4);
    assert_eq!(
        error.error.to_string(),
        "a second root element <project>: an XML file holds one element, the project"
    );
    let error = refused(dom::parse("<project/>\n\n<other/>"), "two roots");
    assert_eq!(error.line, 3);
    // Comments and blanks after the root are XML.
    assert!(dom::parse("<project/>\n<!-- end -->\n").is_ok());
}
