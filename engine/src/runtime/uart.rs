//! The soft PLC's serial port, as LDmicro's UART elements use it (issue
//! #32; docs/ldmicro.md, "The serial port"): bytes typed at it wait to be
//! received, one by each `UART_RECV` with power; a byte sent keeps the
//! transmitter busy for two scans, as LDmicro's simulator counts it.
//! What was sent is kept (the last [`SENT_KEPT`] bytes) with a running
//! total, so that a terminal can show what is new since it last looked —
//! and, the port being part of the machine, time travel shows the
//! terminal as it was.

use std::collections::VecDeque;

/// Bytes typed and not yet received that the port holds: a line typed
/// at once arrives whole (a real chip's FIFO holds two; LDmicro's
/// simulator one).
pub const MAX_WAITING: usize = 4096;

/// The last bytes sent that the port keeps for a terminal to show.
pub const SENT_KEPT: usize = 4096;

/// Scans a byte keeps the transmitter busy (LDmicro's simulator:
/// `SimulateUartTxCountdown = 2`, counted down at each cycle's start).
const BUSY_SCANS: u8 = 2;

/// The serial port.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Uart {
    waiting: VecDeque<u8>,
    busy: u8,
    sent: VecDeque<u8>,
    sent_total: u64,
}

/// Why typing was refused (nothing of it is typed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TypeError {
    /// The port would hold more than [`MAX_WAITING`] bytes.
    Full,
    /// A character that is no byte.
    NotAByte(char),
}

impl std::fmt::Display for TypeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TypeError::Full => write!(
                f,
                "the serial port would hold more than {MAX_WAITING} bytes the program has not \
                 received (docs/limits.md); nothing was typed"
            ),
            TypeError::NotAByte(c) => write!(
                f,
                "`{c}` is not a byte: the serial port takes characters U+0000–U+00FF; nothing \
                 was typed"
            ),
        }
    }
}

impl std::error::Error for TypeError {}

impl Uart {
    /// A scan starts: the byte being sent goes on out.
    pub fn begin_scan(&mut self) {
        self.busy = self.busy.saturating_sub(1);
    }

    /// Whether a byte can be sent now (`UART_SEND_READY`).
    pub fn ready(&self) -> bool {
        self.busy == 0
    }

    /// Sends `byte` if the transmitter is free (else it is lost, as on
    /// LDmicro's chip); whether it went.
    pub fn send(&mut self, byte: u8) -> bool {
        if !self.ready() {
            return false;
        }
        self.busy = BUSY_SCANS;
        if self.sent.len() == SENT_KEPT {
            self.sent.pop_front();
        }
        self.sent.push_back(byte);
        self.sent_total += 1;
        true
    }

    /// Whether a typed byte waits (`UART_RECV_AVAIL`).
    pub fn available(&self) -> bool {
        !self.waiting.is_empty()
    }

    /// The next typed byte, taken.
    pub fn receive(&mut self) -> Option<u8> {
        self.waiting.pop_front()
    }

    /// Types `bytes` at the port: all of them, or none when they would
    /// pass [`MAX_WAITING`].
    pub fn type_bytes(&mut self, bytes: &[u8]) -> Result<(), TypeError> {
        if self.waiting.len() + bytes.len() > MAX_WAITING {
            return Err(TypeError::Full);
        }
        self.waiting.extend(bytes);
        Ok(())
    }

    /// Types the characters of `line` as keys, all of them or nothing;
    /// an empty line is the Enter key alone (a CR, as a terminal sends
    /// it). A line's own Enter sends nothing: LDmicro's programs read
    /// keys one by one, and a CR after each would be a key they did not
    /// ask for.
    pub fn type_line(&mut self, line: &str) -> Result<(), TypeError> {
        if line.is_empty() {
            return self.type_bytes(b"\r");
        }
        let bytes = line
            .chars()
            .map(|c| u8::try_from(u32::from(c)).map_err(|_| TypeError::NotAByte(c)))
            .collect::<Result<Vec<u8>, _>>()?;
        self.type_bytes(&bytes)
    }

    /// Bytes sent since power-on of the port (counting those no longer
    /// kept).
    pub fn sent_total(&self) -> u64 {
        self.sent_total
    }

    /// The bytes sent after the first `seen` of them, as far as they are
    /// kept (the oldest first).
    pub fn sent_after(&self, seen: u64) -> impl Iterator<Item = u8> + '_ {
        let new = self.sent_total.saturating_sub(seen);
        let new = usize::try_from(new)
            .unwrap_or(usize::MAX)
            .min(self.sent.len());
        self.sent.iter().skip(self.sent.len() - new).copied()
    }

    /// Power off and on: what was typed and not received is gone, the
    /// transmitter free; what was sent stays sent.
    pub fn power_cycle(&mut self) {
        self.waiting.clear();
        self.busy = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_byte_keeps_the_transmitter_busy_for_two_scans() {
        let mut u = Uart::default();
        assert!(u.send(b'A'));
        assert!(!u.ready());
        assert!(!u.send(b'B'), "busy: lost");
        u.begin_scan();
        assert!(!u.ready());
        u.begin_scan();
        assert!(u.ready());
        assert!(u.send(b'C'));
        assert_eq!(u.sent_after(0).collect::<Vec<_>>(), b"AC");
        assert_eq!(u.sent_after(1).collect::<Vec<_>>(), b"C");
        assert_eq!(u.sent_total(), 2);
    }

    #[test]
    fn typed_bytes_wait_in_order_up_to_the_limit() {
        let mut u = Uart::default();
        u.type_bytes(b"hi").expect("fits");
        assert!(u.available());
        assert_eq!(u.receive(), Some(b'h'));
        assert_eq!(u.receive(), Some(b'i'));
        assert_eq!(u.receive(), None);
        u.type_bytes(&[b'x'; MAX_WAITING]).expect("fits");
        assert_eq!(u.type_bytes(b"y"), Err(TypeError::Full));
        assert_eq!(u.receive(), Some(b'x'), "nothing of the refused typing");
        u.power_cycle();
        assert!(!u.available());
        assert_eq!(
            u.type_line("ab\u{3042}"),
            Err(TypeError::NotAByte('\u{3042}'))
        );
        assert!(!u.available(), "nothing of a refused line");
        u.type_line("é").expect("a byte");
        assert_eq!(u.receive(), Some(0xE9));
        assert_eq!(u.receive(), None, "no CR after a line");
        u.type_line("").expect("Enter");
        assert_eq!(u.receive(), Some(b'\r'));
    }

    #[test]
    fn only_the_last_bytes_sent_are_kept() {
        let mut u = Uart::default();
        for k in 0..SENT_KEPT + 10 {
            u.begin_scan();
            u.begin_scan();
            assert!(u.send((k % 256) as u8));
        }
        assert_eq!(u.sent_after(0).count(), SENT_KEPT);
        assert_eq!(
            u.sent_after(u.sent_total() - 1).collect::<Vec<_>>(),
            [((SENT_KEPT + 9) % 256) as u8]
        );
    }
}
