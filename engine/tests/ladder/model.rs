//! The grid model: wiring checks, layout, capability tables.
