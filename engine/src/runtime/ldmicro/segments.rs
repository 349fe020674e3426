//! LDmicro's `7SEGMENTS`, `9SEGMENTS`, `14SEGMENTS` and `16SEGMENTS
//! dest src common` (issue #32; docs/ldmicro.md, "Segment displays"): a
//! character turned into the segments a digit lights, inverted for a
//! common-anode digit.
//!
//! The segments sit in the bits LDmicro's source documents for each
//! digit (bit 0 = a … bit 6 = g, bit 7 the point, then the diagonals and
//! halves: [`NAMES`]). The table is laid out as LDmicro's is, so a
//! program's numbers mean what they mean there: 0–15 the hexadecimal
//! digits, 16–31 the same with the point, 32–127 ASCII, 128 the degree
//! sign (`°`, 176, is turned into 128 first). The glyphs are Hashigo's
//! own, drawn from the segments each character conventionally lights (the
//! 7-segment digits and `A`–`F` are the universal codes); a character a
//! digit cannot show is blank. LDmicro's compiler builds only the
//! 7-segment table; the 9-, 14- and 16-segment digits run here in the
//! layout its source gives them.

/// How many entries a table has (LDmicro's `LEN7SEG`).
pub const LEN: i64 = 129;
/// The degree sign's character code, and where it sits in the table.
pub const DEGREE_CHAR: i64 = 0xB0;
const DEGREE: i64 = LEN - 1;
/// The point (bit 7 on every digit).
pub const POINT: u32 = 0x80;

/// What each bit of a digit is, as one letter, by how many segments the
/// digit has: `a`–`f`, `g` (the middle; on 14 and 16 segments its left
/// half g1, `G` its right half g2), `.` the point, the diagonals and
/// centre bars as LDmicro names them (`h` upper left, `i` upper centre,
/// `j` upper right, `m` lower left, `l` lower centre, `k` lower right;
/// on 9 segments `j` and `m` are the two long diagonals), and on 16
/// segments `A` and `D` the right halves of a and d (a and d their left).
pub const fn names(segments: u8) -> &'static str {
    match segments {
        7 => "abcdefg.",
        9 => "abcdefg.jm",
        14 => "abcdefg.jmhiklG",
        _ => "abcdefg.jmhiklGDA",
    }
}

/// A 7-segment digit wired to a variable (the board draws one for each
/// variable a segments element writes).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Display {
    /// The variable, as declared.
    pub name: String,
    /// 7, 9, 14 or 16.
    pub segments: u8,
    /// A common-anode digit: a segment lights when its bit is 0.
    pub anode: bool,
}

/// The bits of a glyph written as its segments' letters in
/// [`names`]`(segments)` order.
const fn glyph(segments: u8, letters: &str) -> u32 {
    let names = names(segments).as_bytes();
    let bytes = letters.as_bytes();
    let mut bits = 0u32;
    let mut i = 0;
    while i < bytes.len() {
        let mut k = 0;
        while k < names.len() {
            if names[k] == bytes[i] {
                bits |= 1 << k;
            }
            k += 1;
        }
        i += 1;
    }
    bits
}

/// The 7-segment hexadecimal digits 0–F (the 9-segment digit takes them).
const HEX7: [&str; 16] = [
    "abcdef", "bc", "abdeg", "abcdg", "bcfg", "acdfg", "acdefg", "abc", "abcdefg", "abcdfg",
    "abcefg", "cdefg", "adef", "bcdeg", "adefg", "aefg",
];

/// ASCII 32–127 on seven segments, in order (blank where a digit cannot
/// show it).
const ASCII7: [&str; 96] = [
    // space ! " # $ % & ' ( ) * + , - . /
    "", "b.", "bf", "", "acdfg", "", "", "b", "adef", "abcd", "", "", "c", "g", ".", "beg",
    // 0–9 : ; < = > ?
    "abcdef", "bc", "abdeg", "abcdg", "bcfg", "acdfg", "acdefg", "abc", "abcdefg", "abcdfg", "", "",
    "", "dg", "", "abeg.", // @ A–O
    "", "abcefg", "cdefg", "adef", "bcdeg", "adefg", "aefg", "acdef", "bcefg", "ef", "bcde",
    "acefg", "def", "aceg", "abcef", "abcdef", // P–Z [ \ ] ^ _
    "abefg", "abcfg", "aef", "acdfg", "defg", "bcdef", "bdf", "bdfg", "bcefg", "bcdfg", "abdeg",
    "adef", "cfg", "abcd", "abf", "d", // ` a–o
    "f", "abcdeg", "cdefg", "deg", "bcdeg", "abdefg", "aefg", "abcdfg", "cefg", "c", "cd", "acefg",
    "ef", "aceg", "ceg", "cdeg", // p–z { | } ~ DEL
    "abefg", "abcfg", "eg", "acdfg", "defg", "cde", "cde", "bdf", "bcefg", "bcdfg", "abdeg",
    "adef", "ef", "abcd", "a", "",
];

/// The characters a 9-segment digit draws with its diagonals (the rest
/// as on seven segments).
const DIAGONAL9: [(u8, &str); 5] = [
    (b'/', "jm"),
    (b'Z', "adjm"),
    (b'z', "adjm"),
    (b'7', "ajm"),
    (b'X', "jm"),
];

/// The 14-segment hexadecimal digits 0–F.
const HEX14: [&str; 16] = [
    "abcdefjm", "bcj", "abdegG", "abcdG", "bcfgG", "acdfgG", "acdefgG", "abc", "abcdefgG",
    "abcdfgG", "abcefgG", "abcdGil", "adef", "abcdil", "adefg", "aefg",
];

/// ASCII 32–127 on fourteen segments, in order; lower-case letters take
/// the capitals' glyphs.
const ASCII14: [&str; 96] = [
    // space ! " # $ % & ' ( ) * + , - . /
    "", "i.", "fi", "bcdgGil", "acdfgGil", "cfjm", "", "j", "jk", "hm", "gGhijklm", "gGil", "m",
    "gG", ".", "jm", // 0–9 : ; < = > ?
    "abcdefjm", "bcj", "abdegG", "abcdG", "bcfgG", "acdfgG", "acdefgG", "abc", "abcdefgG",
    "abcdfgG", "il", "im", "jk", "dgG", "hm", "abGl.", // @ A–O
    "abdefGi", "abcefgG", "abcdGil", "adef", "abcdil", "adefg", "aefg", "acdefG", "bcefgG", "adil",
    "bcde", "efgjk", "def", "bcefhj", "bcefhk", "abcdef", // P–Z [ \ ] ^ _
    "abefgG", "abcdefk", "abefgGk", "acdfgG", "ail", "bcdef", "efjm", "bcefkm", "hjkm", "hjl",
    "adjm", "adef", "hk", "abcd", "km", "d", // ` a–o
    "h", "abcefgG", "abcdGil", "adef", "abcdil", "adefg", "aefg", "acdefG", "bcefgG", "adil",
    "bcde", "efgjk", "def", "bcefhj", "bcefhk", "abcdef", // p–z { | } ~ DEL
    "abefgG", "abcdefk", "abefgGk", "acdfgG", "ail", "bcdef", "efjm", "bcefkm", "hjkm", "hjl",
    "adjm", "adgm", "il", "adGk", "gG", "",
];

/// A whole table: the hexadecimal digits, with the point, ASCII, °.
const fn table(segments: u8, hex: &[&str; 16], ascii: &[&str; 96], degree: &str) -> [u32; 129] {
    let mut t = [0u32; LEN as usize];
    let mut i = 0;
    while i < 16 {
        t[i] = glyph(segments, hex[i]);
        t[i + 16] = glyph(segments, hex[i]) | POINT;
        i += 1;
    }
    let mut c = 0;
    while c < 96 {
        t[32 + c] = glyph(segments, ascii[c]);
        c += 1;
    }
    t[DEGREE as usize] = glyph(segments, degree);
    t
}

const TABLE7: [u32; 129] = table(7, &HEX7, &ASCII7, "abfg");
const TABLE9: [u32; 129] = {
    let mut t = table(9, &HEX7, &ASCII7, "abfg");
    let mut k = 0;
    while k < DIAGONAL9.len() {
        t[DIAGONAL9[k].0 as usize] = glyph(9, DIAGONAL9[k].1);
        k += 1;
    }
    t
};
const TABLE14: [u32; 129] = table(14, &HEX14, &ASCII14, "abfgG");

/// The segments of table entry `at` (an [`index`]) on a digit of
/// `segments` segments (7, 9, 14 or 16; any other is 7).
pub fn glyph_bits(segments: u8, at: i64) -> u32 {
    let at = at.clamp(0, DEGREE) as usize;
    match segments {
        9 => TABLE9[at],
        14 => TABLE14[at],
        16 => {
            // The 14-segment glyph with a and d each in two halves.
            let g = TABLE14[at];
            let split = |bit: u32, right: u32| if g >> bit & 1 != 0 { 1 << right } else { 0 };
            g | split(3, 15) | split(0, 16)
        }
        _ => TABLE7[at],
    }
}

/// The table entry a source selects, as LDmicro's code picks it: `°`
/// (176) is entry 128, anything outside 0–128 is a space. The source
/// variable itself is given that index back (LDmicro writes it).
pub fn index(src: i64) -> i64 {
    if src == DEGREE_CHAR {
        DEGREE
    } else if !(0..LEN).contains(&src) {
        i64::from(b' ')
    } else {
        src
    }
}

/// What a segments element writes for `src`: the source's index (see
/// [`index`]) and the destination's value — the segments, or for a
/// common-anode digit (`anode`) their bitwise NOT as a 32-bit word
/// (LDmicro's `INT_SET_VARIABLE_NOT`; the destination keeps what its
/// width holds).
pub fn convert(segments: u8, src: i64, anode: bool) -> (i64, i64) {
    let at = index(src);
    let bits = i64::from(glyph_bits(segments, at));
    (at, if anode { !bits } else { bits })
}

/// The segments a digit of `segments` segments wired to a variable
/// holding `value` lights: as many low bits as it has segments and its
/// point, inverted for a common-anode digit, whose segments light when
/// their line is low.
pub fn lit(segments: u8, value: i64, anode: bool) -> u32 {
    let width = names(segments).len() as u32;
    let mask = (1u32 << width) - 1;
    let low = value as u32 & mask;
    if anode {
        !low & mask
    } else {
        low
    }
}

/// The letters of the segments in `bits` on a digit of `segments`
/// segments ([`names`]): how tests and the page name a digit's face.
pub fn letters(segments: u8, bits: u32) -> String {
    names(segments)
        .chars()
        .enumerate()
        .filter(|(i, _)| bits >> i & 1 != 0)
        .map(|(_, c)| c)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seven(src: i64, anode: bool) -> (i64, i64) {
        convert(7, src, anode)
    }

    #[test]
    fn the_digits_are_the_datasheet_encoding() {
        // The 7-segment codes every decoder datasheet gives for 0–F
        // (segments a..g in bits 0..6).
        let datasheet = [
            0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F, 0x77, 0x7C, 0x39, 0x5E,
            0x79, 0x71,
        ];
        for (n, code) in datasheet.iter().enumerate() {
            let n = n as i64;
            assert_eq!(seven(n, false), (n, *code), "value {n}");
            assert_eq!(
                seven(n + 16, false).1,
                code | 0x80,
                "value {n} with its point"
            );
            assert_eq!(convert(9, n, false).1, *code, "9 segments: {n}");
        }
        for (c, n) in ('0'..='9').zip(0..) {
            assert_eq!(seven(c as i64, false).1, datasheet[n], "character {c}");
        }
        for (c, n) in ('A'..='F').zip(10..) {
            assert_eq!(seven(c as i64, false).1, datasheet[n], "character {c}");
        }
    }

    fn face(segments: u8, c: char) -> String {
        letters(segments, convert(segments, c as i64, false).1 as u32)
    }

    #[test]
    fn letters_the_digit_can_show_have_their_usual_faces() {
        assert_eq!(face(7, 'H'), "bcefg");
        assert_eq!(face(7, 'L'), "def");
        assert_eq!(face(7, 'P'), "abefg");
        assert_eq!(face(7, 'o'), "cdeg");
        assert_eq!(face(7, '-'), "g");
        assert_eq!(face(7, '_'), "d");
        assert_eq!(face(7, ' '), "");
        assert_eq!(face(7, '.'), ".");
        // Nine segments: the diagonals for Z, the rest as on seven.
        assert_eq!(face(9, 'Z'), "adjm");
        assert_eq!(face(9, 'H'), "bcefg");
        // Fourteen: the diagonals and centre bars.
        assert_eq!(face(14, 'X'), "jmhk");
        assert_eq!(face(14, 'T'), "ail");
        assert_eq!(face(14, 'M'), "bcefjh");
        assert_eq!(face(14, 'N'), "bcefhk");
        assert_eq!(face(14, 'm'), face(14, 'M'), "lower case as the capitals");
        assert_eq!(face(14, '-'), "gG");
        // Sixteen: a and d in halves.
        assert_eq!(face(16, 'T'), "ailA");
        assert_eq!(face(16, 'O'), "abcdefDA");
        assert_eq!(face(16, '-'), "gG");
    }

    #[test]
    fn the_bits_are_where_ldmicros_source_puts_them() {
        // 14 segments: g1 bit 6, j 8, m 9, h 10, i 11, k 12, l 13, g2 14.
        assert_eq!(
            convert(14, i64::from(b'X'), false).1,
            1 << 8 | 1 << 9 | 1 << 10 | 1 << 12
        );
        assert_eq!(convert(14, i64::from(b'-'), false).1, 1 << 6 | 1 << 14);
        // 16 segments: d2 bit 15, a2 bit 16.
        assert_eq!(convert(16, i64::from(b'_'), false).1, 1 << 3 | 1 << 15);
        // 9 segments: j bit 8, m bit 9.
        assert_eq!(convert(9, i64::from(b'/'), false).1, 1 << 8 | 1 << 9);
    }

    #[test]
    fn the_degree_sign_and_numbers_outside_the_table() {
        assert_eq!(seven(DEGREE_CHAR, false), (128, 0x63), "a b f g");
        for outside in [-1, 129, 175, 177, 1000, i64::MIN] {
            assert_eq!(seven(outside, false), (32, 0), "{outside}: a space");
            assert_eq!(convert(16, outside, false), (32, 0));
        }
        assert_eq!(index(128), 128);
    }

    #[test]
    fn a_common_anode_digit_takes_the_inverse() {
        assert_eq!(seven(8, true).1, !0x7F);
        assert_eq!(seven(1, true).1 & 0xFF, 0xF9, "the usual anode code of 1");
        assert_eq!(lit(7, seven(1, true).1, true), 0x06, "drawn: b and c lit");
        assert_eq!(lit(7, 0x1_06, false), 0x06, "only the low byte is wired");
        assert_eq!(letters(7, 0x86), "bc.");
        let x = convert(14, i64::from(b'X'), true).1;
        assert_eq!(letters(14, lit(14, x, true)), "jmhk");
    }
}
