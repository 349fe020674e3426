//! The ladder model, compilers, decompilers and formats (issue #6).

mod differential;
mod model;
mod seed;
