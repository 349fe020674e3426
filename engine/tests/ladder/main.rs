//! The ladder model, compilers, decompilers and formats (issue #6).

mod cli;
#[path = "../common/mod.rs"]
mod common;
mod declare;
mod decompile;
mod differential;
mod documents;
mod exercise;
mod gates;
mod model;
mod networks;
mod plcopen;
mod plcopen_st_boxes;
mod robustness;
mod seed;
mod share;
mod soft_drawn;
mod soft_externals;
mod soft_feedback;
mod soft_plcopen;
mod soft_seeds;
mod soft_st;
mod soft_st_export;
mod source_map;
mod st_boxes;
mod st_project;
mod strategies;
mod why;
mod words;
