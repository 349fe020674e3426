//! LDmicro's word operations as its simulator computes them: in 32
//! bits, kept in the destination's width (issue #32; docs/ldmicro.md,
//! "Elements").

/// LDmicro's word operation `op` on `a` and `b` (`d` the destination as
/// it is) in a `bits`-wide signed word, wrapped to it: as LDmicro's
/// simulator computes in 32 bits and keeps what the destination's size
/// holds. A division or remainder by zero leaves `d` as it was.
pub(super) fn word_op(op: &str, a: i64, b: i64, d: i64, bits: i64) -> i64 {
    let bits = bits.clamp(1, 32) as u32;
    let mask: u64 = (1u64 << bits) - 1;
    let unsigned = |v: i64| (v as u64) & mask;
    let shift = b.clamp(0, 63) as u32;
    let rotate = |left: bool| {
        let n = (b.rem_euclid(i64::from(bits))) as u32;
        let v = unsigned(a);
        if n == 0 {
            v
        } else if left {
            (v << n) | (v >> (bits - n))
        } else {
            (v >> n) | (v << (bits - n))
        }
    };
    let r: u64 = match op {
        "ADD" => a.wrapping_add(b) as u64,
        "SUB" => a.wrapping_sub(b) as u64,
        "MUL" => a.wrapping_mul(b) as u64,
        "DIV" => a.checked_div(b).unwrap_or(d) as u64,
        "MOD" => a.checked_rem(b).unwrap_or(d) as u64,
        "AND" => (a & b) as u64,
        "OR" => (a | b) as u64,
        "XOR" => (a ^ b) as u64,
        "SHL" => (a as u64) << shift,
        // LDmicro's SHR keeps the sign (SR0 fills with zeros).
        "SHR" => (a >> shift) as u64,
        "ROL" => rotate(true),
        "ROR" => rotate(false),
        "MOVE" => a as u64,
        "NOT" => !a as u64,
        "NEG" => a.wrapping_neg() as u64,
        "BIN2BCD" => {
            let (mut v, mut out, mut shift) = (a.unsigned_abs(), 0u64, 0);
            while v > 0 && shift < 64 {
                out |= (v % 10) << shift;
                v /= 10;
                shift += 4;
            }
            out
        }
        "BCD2BIN" => {
            let (mut v, mut out, mut scale) = (unsigned(a), 0u64, 1u64);
            while v > 0 {
                out = out.wrapping_add((v & 0xF).wrapping_mul(scale));
                v >>= 4;
                scale = scale.wrapping_mul(10);
            }
            out
        }
        "SWAP" => {
            let bytes = (bits / 8).max(1);
            let mut v = unsigned(a);
            let mut out = 0u64;
            for _ in 0..bytes {
                out = (out << 8) | (v & 0xFF);
                v >>= 8;
            }
            out
        }
        "OPPOSITE" => unsigned(a).reverse_bits() >> (64 - bits),
        "SR0" => unsigned(a) >> b.clamp(0, 63),
        "SETBIT" => unsigned(d) | (1u64 << b.clamp(0, 63)),
        "CLRBIT" => unsigned(d) & !(1u64 << b.clamp(0, 63)),
        _ => unsigned(d),
    } & mask;
    // Back to a signed word of that width.
    let sign = 1u64 << (bits - 1);
    (r ^ sign) as i64 - sign as i64
}
