//! The fast path: whole scans from program memory decoded once.
//!
//! Two kernels share the work:
//! - [`network`] runs a scan as a compiled network of lookup-table gates. It
//!   is speculative: it only stands when no timer or counter latch changes
//!   in the scan, which is most scans;
//! - [`steps`] runs the decoded steps one by one and acts on the timers and
//!   the counter where a store changes them. It is exact for every scan and
//!   runs whenever the network's result is refused.
//!
//! Both are tested against the exact path (one clock edge at a time).

mod network;
mod steps;

use network::{Network, Slots, Specials};
pub(super) use steps::ScanDevices;
use steps::{special_latches, DecodedProgram};

use super::asm::STEPS;

/// Program memory decoded for both kernels; rebuilt after any write.
#[derive(Clone, Debug)]
pub(super) struct FastCode {
    memory: [u8; STEPS],
    steps: DecodedProgram,
    /// One network per timer and counter state ([`Specials::key`]),
    /// compiled the first time a scan starts in that state.
    networks: Box<[Option<Network>]>,
    slots: Slots,
    backoff: Backoff,
}

impl FastCode {
    /// Decodes program memory for both kernels.
    pub(super) fn decode(memory: &[u8; STEPS]) -> FastCode {
        FastCode {
            memory: *memory,
            steps: DecodedProgram::decode(memory),
            networks: vec![None; Specials::KEYS].into_boxed_slice(),
            slots: Slots::default(),
            backoff: Backoff::default(),
        }
    }

    /// Runs all 256 steps from PC 0; returns the accumulator and the bus
    /// after the last step. `speculate` lets the gate network try first.
    pub(super) fn run_scan(
        &mut self,
        bus: u32,
        acc: bool,
        devices: &mut ScanDevices<'_>,
        speculate: bool,
    ) -> (bool, u32) {
        if speculate && self.backoff.try_network() {
            let specials = Specials {
                reads: bus,
                latches: special_latches(devices.timers, devices.counter),
            };
            let memory = &self.memory;
            let network = self.networks[specials.key()]
                .get_or_insert_with(|| Network::compile(memory, specials));
            match network.run(&mut self.slots, bus, acc) {
                Some(result) => {
                    self.backoff.succeeded();
                    return result;
                }
                None => self.backoff.failed(),
            }
        }
        steps::run_scan(&self.steps, bus, acc, devices)
    }
}

/// How often the network is tried after it was refused. A refused try costs
/// a fraction of a step-kernel scan; after consecutive refusals the next
/// 1, 2, 4 … 64 scans skip it, so a program whose devices act on every scan
/// loses little, and one whose devices act now and then loses one scan.
#[derive(Clone, Copy, Debug, Default)]
struct Backoff {
    /// Scans still to run on the step kernel.
    skip: u32,
    /// How many the next refusal makes skip.
    penalty: u32,
}

impl Backoff {
    const MAX_PENALTY: u32 = 64;

    fn try_network(&mut self) -> bool {
        if self.skip == 0 {
            return true;
        }
        self.skip -= 1;
        false
    }

    fn succeeded(&mut self) {
        self.penalty = 0;
    }

    fn failed(&mut self) {
        self.penalty = (self.penalty * 2).clamp(1, Self::MAX_PENALTY);
        self.skip = self.penalty;
    }
}

#[cfg(test)]
mod tests {
    use super::Backoff;

    /// Which of the next `scans` scans try the network, with every try
    /// refused.
    fn tries_while_refused(backoff: &mut Backoff, scans: usize) -> Vec<usize> {
        let mut tries = Vec::new();
        for scan in 0..scans {
            if backoff.try_network() {
                tries.push(scan);
                backoff.failed();
            }
        }
        tries
    }

    #[test]
    fn refusals_back_off_doubling_to_64_scans_and_a_success_resets() {
        let mut backoff = Backoff::default();
        // Skips of 1, 2, 4, 8, 16, 32, 64, 64 scans after each refusal.
        let tries = tries_while_refused(&mut backoff, 300);
        assert_eq!(tries, [0, 2, 5, 10, 19, 36, 69, 134, 199, 264]);
        // A success after the skip: the next refusal skips one scan again.
        while !backoff.try_network() {}
        backoff.succeeded();
        assert_eq!(tries_while_refused(&mut backoff, 6), [0, 2, 5]);
    }
}
