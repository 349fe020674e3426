//! Issue #43, round 3: il.
