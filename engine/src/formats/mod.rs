//! Other tools' files, read into ladders and written back: PLCopen XML
//! ([`plcopen`], IEC 61131-10 TC6: drawn LD/FBD bodies and IL, for the bit
//! machines' lowering and for the soft PLC as written) and LDmicro's `.ld`
//! files ([`ldmicro`]). Each reads text into a document, then a model,
//! then a ladder for a machine; none is imported by `ladder/`. Hashigo's
//! own project files and share links are still `ladder::project` and
//! `ladder::share`.

pub mod ldmicro;
pub mod plcopen;
