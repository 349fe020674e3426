//! LDmicro's `7SEGMENTS dest src common` (issue #32; docs/ldmicro.md,
//! "Segment displays"): a character turned into the segments a 7-segment
//! digit lights, bit 0 = a … bit 6 = g, bit 7 = the point (the order every
//! datasheet and LDmicro use), inverted for a common-anode digit.
//!
//! The table is laid out as LDmicro's is, so a program's numbers mean
//! what they mean there: 0–15 the hexadecimal digits, 16–31 the same with
//! the point, 32–127 ASCII, 128 the degree sign (`°`, 176, is turned into
//! 128 first). The glyphs are Hashigo's own, drawn from the segments each
//! character conventionally lights (the digits and `A`–`F` are the
//! universal ones); a character a digit cannot show is blank.

/// A 7-segment digit wired to a variable (the board draws one for each
/// variable a `7SEGMENTS` writes).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Display {
    /// The variable, as declared.
    pub name: String,
    /// A common-anode digit: a segment lights when its bit is 0.
    pub anode: bool,
}

/// How many entries the table has (LDmicro's `LEN7SEG`).
pub const LEN: i64 = 129;
/// The degree sign's character code, and where it sits in the table.
pub const DEGREE_CHAR: i64 = 0xB0;
const DEGREE: i64 = LEN - 1;
/// The point (bit 7).
pub const POINT: u8 = 0x80;

/// Segments of a glyph written as its letters (`"abcdefg"`, `.` the
/// point).
const fn glyph(segments: &str) -> u8 {
    let bytes = segments.as_bytes();
    let mut bits = 0u8;
    let mut i = 0;
    while i < bytes.len() {
        bits |= match bytes[i] {
            b'a'..=b'g' => 1 << (bytes[i] - b'a'),
            b'.' => POINT,
            _ => 0,
        };
        i += 1;
    }
    bits
}

/// The hexadecimal digits 0–F.
const HEX: [&str; 16] = [
    "abcdef", "bc", "abdeg", "abcdg", "bcfg", "acdfg", "acdefg", "abc", "abcdefg", "abcdfg",
    "abcefg", "cdefg", "adef", "bcdeg", "adefg", "aefg",
];

/// ASCII 32–127, in order (blank where a digit cannot show it).
const ASCII: [&str; 96] = [
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

/// The whole table, built once at compile time.
const TABLE: [u8; LEN as usize] = {
    let mut t = [0u8; LEN as usize];
    let mut i = 0;
    while i < 16 {
        t[i] = glyph(HEX[i]);
        t[i + 16] = glyph(HEX[i]) | POINT;
        i += 1;
    }
    let mut c = 0;
    while c < 96 {
        t[32 + c] = glyph(ASCII[c]);
        c += 1;
    }
    t[DEGREE as usize] = glyph("abfg");
    t
};

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

/// What `7SEGMENTS` writes for `src`: the source's index (see [`index`])
/// and the destination's value — the segments, or for a common-anode
/// digit (`anode`) their bitwise NOT as a 32-bit word (LDmicro's
/// `INT_SET_VARIABLE_NOT`; the destination keeps what its width holds).
pub fn seven(src: i64, anode: bool) -> (i64, i64) {
    let at = index(src);
    let bits = i64::from(TABLE[at as usize]);
    (at, if anode { !bits } else { bits })
}

/// The segments a digit wired to a variable holding `value` lights (bit
/// 0 = a … bit 7 = the point): the low byte, inverted for a common-anode
/// digit, whose segments light when their line is low.
pub fn lit(value: i64, anode: bool) -> u8 {
    let low = (value & 0xFF) as u8;
    if anode {
        !low
    } else {
        low
    }
}

/// The letters of the segments in `bits` (`"abcdefg."`): how tests and
/// the page name a digit's face.
pub fn letters(bits: u8) -> String {
    (0..8)
        .filter(|i| bits >> i & 1 != 0)
        .map(|i| if i == 7 { '.' } else { char::from(b'a' + i) })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

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
        }
        for (c, n) in ('0'..='9').zip(0..) {
            assert_eq!(seven(c as i64, false).1, datasheet[n], "character {c}");
        }
        for (c, n) in ('A'..='F').zip(10..) {
            assert_eq!(seven(c as i64, false).1, datasheet[n], "character {c}");
        }
    }

    #[test]
    fn letters_the_digit_can_show_have_their_usual_faces() {
        let face = |c: char| letters(seven(c as i64, false).1 as u8);
        assert_eq!(face('H'), "bcefg");
        assert_eq!(face('L'), "def");
        assert_eq!(face('P'), "abefg");
        assert_eq!(face('o'), "cdeg");
        assert_eq!(face('-'), "g");
        assert_eq!(face('_'), "d");
        assert_eq!(face(' '), "");
        assert_eq!(face('.'), ".");
    }

    #[test]
    fn the_degree_sign_and_numbers_outside_the_table() {
        assert_eq!(seven(DEGREE_CHAR, false), (128, 0x63), "a b f g");
        for outside in [-1, 129, 175, 177, 1000, i64::MIN] {
            assert_eq!(seven(outside, false), (32, 0), "{outside}: a space");
        }
        assert_eq!(index(128), 128);
    }

    #[test]
    fn a_common_anode_digit_takes_the_inverse() {
        assert_eq!(seven(8, true).1, !0x7F);
        assert_eq!(seven(1, true).1 & 0xFF, 0xF9, "the usual anode code of 1");
        assert_eq!(lit(seven(1, true).1, true), 0x06, "drawn: b and c lit");
        assert_eq!(lit(0x1_06, false), 0x06, "only the low byte is wired");
        assert_eq!(letters(0x86), "bc.");
    }
}
