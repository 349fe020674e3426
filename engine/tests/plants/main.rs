//! Plants (issue #50) on the command line: `hashigo plants`, and the
//! plant options of `run`, `test` and `why`, run as a process
//! (../shared/spec/cli.md, "Plants").

#[path = "../common/mod.rs"]
mod common;

mod cli;
mod examples;
mod exercises;
mod four;
mod project;
mod properties;
mod record;
