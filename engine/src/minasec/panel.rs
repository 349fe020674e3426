//! The front panel as plain data: what every LED, digit and control shows,
//! so a front end can draw the board without knowing the machine.

use super::control::{ClockSpeed, Mode, TimerId};
use super::machine::Machine;
use crate::time::SimTime;

/// Segments a..g (bits 0..6) that the 74HC4511 lights for a BCD digit.
pub const fn seven_segments(digit: u8) -> u8 {
    // Standard 4511 patterns (6 without the a tail, 9 without the d tail).
    const PATTERNS: [u8; 10] = [
        0b011_1111, 0b000_0110, 0b101_1011, 0b100_1111, 0b110_0110, 0b110_1101, 0b111_1100,
        0b000_0111, 0b111_1111, 0b110_0111,
    ];
    if digit < 10 {
        PATTERNS[digit as usize]
    } else {
        0 // the 4511 blanks codes above 9
    }
}

/// The clock-level signals of the seed's timing chart (動作タイミング).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CpuSignals {
    /// The clock line.
    pub clk: bool,
    /// The instruction byte on the instruction bus.
    pub instruction: u8,
    /// The operand address on the address bus.
    pub address: u8,
    /// The input data bus: what the addressed device reads.
    pub din: bool,
    /// The output data bus: the accumulator, inverted for `STI`.
    pub dout: bool,
    /// The write strobe, active low: `WE = !(OP1·OP2·CLK)`.
    pub we: bool,
}

/// Everything the board shows and every control's position.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Panel {
    /// The 5 V supply.
    pub power: bool,
    /// RUN-HALT-RESET.
    pub mode: Option<Mode>,
    /// SLOW-FAST (a custom oscillator shows as FAST).
    pub slow: bool,
    /// PC LEDs, bit n = PC bit n.
    pub pc_leds: u8,
    /// Instruction LEDs: the byte at PC.
    pub instruction_leds: u8,
    /// The accumulator LED.
    pub acc_led: bool,
    /// Input switches X00..X07 (positions, not the image).
    pub input_switches: u8,
    /// Output lamps Y00..Y07.
    pub lamps: u8,
    /// The two digits (tens, ones); `None` when dark (power off).
    pub digits: Option<(u8, u8)>,
    /// RV1 and RV2 as the delays they give.
    pub delays: [SimTime; 2],
    /// The rotary switches (tens, ones).
    pub preset: (u8, u8),
    /// The eight DIP switches (bit 7 = OP2 .. bit 0 = A0).
    pub dip: u8,
    /// WRITE held.
    pub write_held: bool,
    /// CLOCK held.
    pub clock_held: bool,
    /// CNTCLR held.
    pub count_clear_held: bool,
    /// The clock-level view of the CPU.
    pub cpu: CpuSignals,
}

impl Machine {
    /// Fills `panel` with what the board shows now. The caller owns the
    /// struct, so a front end can keep one and compare it field by field.
    pub fn panel_into(&self, panel: &mut Panel) {
        let on = self.powered();
        let counter = self.counter();
        let instruction = self.instruction();
        panel.power = on;
        panel.mode = Some(self.mode());
        panel.slow = self.speed() == ClockSpeed::Slow;
        // Every LED is driven from the main supply: dark when it is off.
        panel.pc_leds = if on { self.pc() } else { 0 };
        panel.instruction_leds = if on { instruction.encode() } else { 0 };
        panel.acc_led = on && self.acc();
        panel.input_switches = self.input_terminals();
        panel.lamps = if on { self.output_terminals() } else { 0 };
        panel.digits = on.then(|| (counter.count() / 10, counter.count() % 10));
        panel.delays = [
            self.timer(TimerId::T0).delay(),
            self.timer(TimerId::T1).delay(),
        ];
        panel.preset = (counter.set_value() / 10, counter.set_value() % 10);
        panel.dip = self.dip();
        panel.write_held = self.write_held;
        panel.clock_held = self.clock_held;
        panel.count_clear_held = counter.clear_button();
        panel.cpu = self.cpu_signals();
    }

    /// A fresh panel snapshot.
    pub fn panel(&self) -> Panel {
        let mut panel = Panel::default();
        self.panel_into(&mut panel);
        panel
    }

    /// The timing chart's signals, as the CPU view has them (dark when
    /// off).
    fn cpu_signals(&self) -> CpuSignals {
        let mut v = super::cpu::CpuView::default();
        self.cpu_view_into(&mut v);
        CpuSignals {
            clk: v.clk,
            instruction: v.instruction,
            address: v.address,
            din: v.data_in,
            dout: v.data_out,
            we: v.we,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_for_each_digit() {
        assert_eq!(seven_segments(0), 0x3F);
        assert_eq!(seven_segments(1), 0x06);
        assert_eq!(seven_segments(8), 0x7F);
        assert_eq!(seven_segments(10), 0);
    }
}
