//! The third round of hostile input (issue #43): the soft PLC's IL, LDmicro
//! files and PLCopen projects as written. Each test failed on the main
//! branch before the fix it names.

mod files;
mod il;
mod il_bodies;
mod il_chains;
mod ldmicro;
