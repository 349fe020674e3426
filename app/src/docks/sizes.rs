//! The docks' sizes and the tools they show, as plain data: read from and
//! written to storage, clamped to the window (tested natively).

/// A tool of the bottom dock. Its hook names its tab (`dock-tab-<hook>`)
/// and its panel (`data-dock-panel="<hook>"`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tool {
    /// The watch table and the inputs held from the ladder.
    Watch,
    /// The timing chart.
    Chart,
    /// The ladder tests.
    Tests,
    /// Why? on the cursor's cell.
    Why,
    /// The compiled listing and the ladder's problems.
    Listing,
    /// The cursor's rung comment and its device's comment.
    Comments,
    /// The soft PLC's declared variables.
    Variables,
    /// The machine's program text.
    Program,
    /// MINASEC-U's view inside its CPU.
    Cpu,
    /// The plant the ladder controls (issue #52).
    Plant,
    /// On a phone only: the machine's whole panel, in the sheet.
    Panel,
}

impl Tool {
    /// Every tool, in tab order.
    pub const ALL: [Tool; 11] = [
        Tool::Watch,
        Tool::Chart,
        Tool::Tests,
        Tool::Why,
        Tool::Listing,
        Tool::Comments,
        Tool::Variables,
        Tool::Program,
        Tool::Cpu,
        Tool::Plant,
        Tool::Panel,
    ];

    /// Its hook.
    pub const fn hook(self) -> &'static str {
        match self {
            Tool::Watch => "watch",
            Tool::Chart => "chart",
            Tool::Tests => "tests",
            Tool::Why => "why",
            Tool::Listing => "listing",
            Tool::Comments => "comments",
            Tool::Variables => "variables",
            Tool::Program => "program",
            Tool::Cpu => "cpu",
            Tool::Plant => "plant",
            Tool::Panel => "panel",
        }
    }

    /// The tool with `hook`.
    pub fn from_hook(hook: &str) -> Option<Tool> {
        Tool::ALL.into_iter().find(|t| t.hook() == hook)
    }

    /// Whether `machine`'s workspace has this tool: the variables are the
    /// soft PLC's, the CPU view MINASEC-U's.
    pub fn on(self, machine: engine::MachineId) -> bool {
        match self {
            Tool::Variables => machine.target().capabilities().word_boxes,
            Tool::Cpu => machine.target().steps_clocks(),
            _ => true,
        }
    }
}

/// The docks' sizes in CSS pixels and which are open.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sizes {
    /// The panel dock's width.
    pub right_px: f64,
    /// The tools dock's height.
    pub bottom_px: f64,
    pub right_open: bool,
    pub bottom_open: bool,
    /// The tool last shown.
    pub tool: Tool,
}

/// The narrowest panel dock and the lowest tools dock a splitter leaves.
pub const MIN_RIGHT_PX: f64 = 260.0;
pub const MIN_BOTTOM_PX: f64 = 110.0;

impl Default for Sizes {
    /// A panel dock of 26 rem and a tools dock of about a fifth of a
    /// laptop's height: the whole rung and the panel fit at 1366×768.
    fn default() -> Sizes {
        Sizes {
            right_px: 400.0,
            bottom_px: 170.0,
            right_open: true,
            bottom_open: true,
            tool: Tool::Watch,
        }
    }
}

impl Sizes {
    /// The sizes as storage keeps them: `right,bottom,right open,bottom
    /// open,tool` (`400,170,1,1,watch`).
    pub fn to_text(&self) -> String {
        format!(
            "{:.0},{:.0},{},{},{}",
            self.right_px,
            self.bottom_px,
            u8::from(self.right_open),
            u8::from(self.bottom_open),
            self.tool.hook()
        )
    }

    /// Sizes read back; `None` for anything that does not read (the
    /// defaults are used then).
    pub fn parse(text: &str) -> Option<Sizes> {
        let mut parts = text.split(',');
        let mut number = || {
            parts
                .next()?
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|n| n.is_finite())
        };
        let right_px = number()?.max(MIN_RIGHT_PX);
        let bottom_px = number()?.max(MIN_BOTTOM_PX);
        let right_open = number()? != 0.0;
        let bottom_open = number()? != 0.0;
        let tool = Tool::from_hook(parts.next()?.trim())?;
        parts.next().is_none().then_some(Sizes {
            right_px,
            bottom_px,
            right_open,
            bottom_open,
            tool,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_back_what_they_wrote() {
        let s = Sizes {
            right_px: 512.0,
            bottom_px: 240.0,
            right_open: false,
            bottom_open: true,
            tool: Tool::Tests,
        };
        assert_eq!(s.to_text(), "512,240,0,1,tests");
        assert_eq!(Sizes::parse(&s.to_text()), Some(s));
    }

    #[test]
    fn what_does_not_read_is_refused_and_small_sizes_grow() {
        for bad in [
            "",
            "1,2",
            "400,190,1,1,nope",
            "NaN,190,1,1,watch",
            "400,190,1,1,watch,9",
        ] {
            assert_eq!(Sizes::parse(bad), None, "{bad}");
        }
        let tiny = Sizes::parse("3,4,1,1,why").expect("reads");
        assert_eq!(
            (tiny.right_px, tiny.bottom_px),
            (MIN_RIGHT_PX, MIN_BOTTOM_PX)
        );
    }

    #[test]
    fn every_tool_has_its_own_hook() {
        for t in Tool::ALL {
            assert_eq!(Tool::from_hook(t.hook()), Some(t));
        }
        assert!(Tool::Cpu.on(engine::MachineId::MinasecU));
        assert!(!Tool::Cpu.on(engine::MachineId::Io86a));
        assert!(Tool::Variables.on(engine::MachineId::SoftPlc));
        assert!(!Tool::Variables.on(engine::MachineId::AvrPlc));
    }
}
