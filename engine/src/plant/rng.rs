//! The plants' seeded schedule: SplitMix64, integer only, so the same
//! seed gives the same arrivals on every host.

/// A SplitMix64 generator.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Rng(u64);

impl Rng {
    /// A generator from `seed`.
    pub(crate) fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..=max` (`max` ≥ 0); the tiny bias of a modulo is
    /// of no matter for a schedule.
    pub(crate) fn up_to(&mut self, max: i64) -> i64 {
        let span = u64::try_from(max).unwrap_or(0).saturating_add(1);
        i64::try_from(self.next() % span).unwrap_or(0)
    }

    /// When the next of a seeded series comes: `every` ms after `now_ms`
    /// and a random `0..=spread` more (every plant's arrivals and presses).
    pub(crate) fn after(&mut self, now_ms: i64, every: i64, spread: i64) -> i64 {
        now_ms.saturating_add(every + self.up_to(spread))
    }
}

#[cfg(test)]
mod tests {
    use super::Rng;

    #[test]
    fn the_same_seed_gives_the_same_numbers_within_range() {
        let (mut a, mut b, mut c) = (Rng::new(7), Rng::new(7), Rng::new(8));
        let xs: Vec<i64> = (0..100).map(|_| a.up_to(1000)).collect();
        let ys: Vec<i64> = (0..100).map(|_| b.up_to(1000)).collect();
        let zs: Vec<i64> = (0..100).map(|_| c.up_to(1000)).collect();
        assert_eq!(xs, ys);
        assert_ne!(xs, zs);
        assert!(xs.iter().all(|x| (0..=1000).contains(x)));
        assert_eq!(Rng::new(1).up_to(0), 0);
    }
}
