//! The bit machines' lowering of a drawn body, second phase after
//! [`super::graph`]: the body's graph read into electrical points, edges
//! and outputs ([`body`], [`read`]), then what the machine cannot run
//! natively lowered to contacts, coils and helper relays: the blocks'
//! order and wired ORs ([`joins`]), boolean blocks, flip-flops, counters'
//! resets, TOF/TP ([`gates`]), timers, counters, edges and comparisons
//! ([`blocks`]). The rungs are drawn from the result by [`super::rungs`].

pub(in crate::formats::plcopen) mod blocks;
pub(in crate::formats::plcopen) mod body;
mod gates;
mod joins;
mod read;
