//! IEC 61131-3's comparison functions (GT, GE, EQ, NE, LE, LT), named
//! once for every layer: the soft PLC's IL operators, PLCopen's
//! comparison blocks, the ladder's boxes.

use std::cmp::Ordering;

/// A comparison of two values of one type.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Comparison {
    /// `GT`: greater than.
    Gt,
    /// `GE`: greater than or equal.
    Ge,
    /// `EQ`: equal.
    Eq,
    /// `NE`: not equal.
    Ne,
    /// `LE`: less than or equal.
    Le,
    /// `LT`: less than.
    Lt,
}

impl Comparison {
    /// Every comparison with its IEC name.
    pub const ALL: [(Comparison, &'static str); 6] = [
        (Comparison::Gt, "GT"),
        (Comparison::Ge, "GE"),
        (Comparison::Eq, "EQ"),
        (Comparison::Ne, "NE"),
        (Comparison::Le, "LE"),
        (Comparison::Lt, "LT"),
    ];

    /// Its IEC name (`GT`).
    pub fn name(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(c, _)| *c == self)
            .map_or("EQ", |(_, n)| n)
    }

    /// Whether it holds for `a` compared to `b` being `order`.
    pub fn holds(self, order: Ordering) -> bool {
        match self {
            Comparison::Gt => order == Ordering::Greater,
            Comparison::Ge => order != Ordering::Less,
            Comparison::Eq => order == Ordering::Equal,
            Comparison::Ne => order != Ordering::Equal,
            Comparison::Le => order != Ordering::Greater,
            Comparison::Lt => order == Ordering::Less,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Comparison;
    use std::cmp::Ordering::{Equal, Greater, Less};

    #[test]
    fn each_comparison_holds_for_its_orders() {
        let holds = |c: Comparison| [Less, Equal, Greater].map(|o| c.holds(o));
        assert_eq!(holds(Comparison::Gt), [false, false, true]);
        assert_eq!(holds(Comparison::Ge), [false, true, true]);
        assert_eq!(holds(Comparison::Eq), [false, true, false]);
        assert_eq!(holds(Comparison::Ne), [true, false, true]);
        assert_eq!(holds(Comparison::Le), [true, true, false]);
        assert_eq!(holds(Comparison::Lt), [true, false, false]);
    }
}
