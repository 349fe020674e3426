//! The registry: the one place that names every machine. It sits above
//! both the machine interface (`plc/`, which names none) and the machine
//! folders, so adding a machine is its folder, one line in [`new_plc`] and
//! its target table (docs/architecture.md, "Adding a machine").

pub use crate::arduino::ArduinoPlc;
pub use crate::avr::AvrPlc;
pub use crate::io86a::Io86aPlc;
pub use crate::minasec::MinasecPlc;
pub use crate::softplc::SoftPlc;

use crate::plc::Plc;
use crate::MachineId;

/// A new machine of kind `id`, powered on, with no program, ready to run
/// (MINASEC-U's switch at RUN, the Arduino PLC enabled).
pub fn new_plc(id: MachineId) -> Box<dyn Plc> {
    match id {
        MachineId::MinasecU => Box::new(MinasecPlc::new()),
        MachineId::Io86a => Box::new(Io86aPlc::new()),
        MachineId::AvrPlc => Box::new(AvrPlc::new()),
        MachineId::ArduinoPlc => Box::new(ArduinoPlc::new()),
        MachineId::SoftPlc => Box::new(SoftPlc::new()),
    }
}
