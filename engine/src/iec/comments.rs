//! IEC comments over several lines: blanked before the line readers
//! (declarations, IL) see the text, so that each keeps its line number.

/// `text` with every comment that spans lines blanked out (its line
/// breaks kept, so every line keeps its number); a comment on one line
/// stays for the line's own reader (a declaration keeps it). A comment
/// never closed is left as it is: the line that opens it says so.
pub(crate) fn blank_long_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find("(*") {
        out.push_str(&rest[..at]);
        let body = &rest[at..];
        let Some(end) = body.find("*)").map(|e| e + 2) else {
            out.push_str(body);
            return out;
        };
        let comment = &body[..end];
        if comment.contains('\n') {
            out.extend(comment.chars().map(|c| if c == '\n' { '\n' } else { ' ' }));
        } else {
            out.push_str(comment);
        }
        rest = &body[end..];
    }
    out.push_str(rest);
    out
}
