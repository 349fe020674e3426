//! The tools' panes the bottom dock shows (issue #45): the Tests pane,
//! the timing chart, Why?, the listing and problems, the variables, and
//! the sheets the menus open (Find, Projects).

pub mod cases;
pub mod chart;
mod chart_window;
pub mod exercise;
pub mod find;
pub mod parts;
pub mod projects;
pub mod runner;
pub mod side;
pub mod variables;
pub mod why;
