//! The online view of Structured Text (issue #55): where each step of
//! the program running comes from in the ST text, and in which instance's
//! call it runs. With it the page shows values beside the lines of a
//! block called from the ladder (one instance's), stops at a breakpoint
//! in its body, steps by statement there, and Why? names the write that
//! ran in the instance's call.

use std::ops::RangeInclusive;

use super::program::{InstanceBody, Program, Step};
use super::st::StBlocks;
use super::st_why::StWrite;
use crate::iec::st::ast::{Item, PouKind};
use crate::iec::st::parse_source;

/// Each step of a program with its ST line and the instance whose call
/// runs it.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct StMap {
    /// `lines[step]`: the 1-based ST line the step comes from (`None`
    /// for a ladder's own steps and the steps the loader adds).
    pub lines: Vec<Option<usize>>,
    /// `owners[step]`: the instance (an index of `instances`) whose body
    /// the step is, the innermost (`None`: the program's own steps).
    pub owners: Vec<Option<usize>>,
    /// The program's instances of its own blocks.
    pub instances: Vec<InstanceBody>,
}

impl StMap {
    /// The map of `program` whose steps come from ST lines `lines`
    /// (`StRun::lines` for an ST program). A step that only passes
    /// control on (an `IF` branch's jump to its end, the return at a
    /// body's last label) has no line: stepping by statement goes from a
    /// branch's last statement to the one after `END_IF`, not back to
    /// the `IF`'s line that lowered it.
    pub fn new(program: &Program, mut lines: Vec<Option<usize>>) -> StMap {
        let instances = program.instance_bodies();
        let ends: Vec<usize> = instances.iter().map(|i| i.steps.start).collect();
        for (step, line) in lines.iter_mut().enumerate() {
            let last = matches!(program.steps.get(step + 1), None | Some(Step::Return))
                || ends.contains(&(step + 1));
            match program.steps.get(step) {
                Some(Step::Jmp(None, _)) => *line = None,
                Some(Step::Ret(None)) if last => *line = None,
                _ => {}
            }
        }
        let mut owners = vec![None; program.len()];
        for (i, body) in instances.iter().enumerate() {
            for step in body.steps.clone() {
                if let Some(owner) = owners.get_mut(step) {
                    *owner = Some(i);
                }
            }
        }
        StMap {
            lines,
            owners,
            instances,
        }
    }

    /// The map of a ladder's program, loaded from `loaded` (the ladder's
    /// IL followed by `blocks.il`, as the soft PLC compiles a ladder
    /// calling ST blocks): the blocks' steps by their ST lines.
    pub fn for_ladder(program: &Program, loaded: &str, blocks: &StBlocks) -> StMap {
        StMap::new(program, blocks.step_lines(program, loaded))
    }

    /// The ST line of step `step` and the instance whose call runs it.
    pub fn place(&self, step: usize) -> Option<(usize, Option<usize>)> {
        let line = self.lines.get(step).copied().flatten()?;
        Some((line, self.owners.get(step).copied().flatten()))
    }

    /// The instance named `name` (any case).
    pub fn instance(&self, name: &str) -> Option<usize> {
        self.instances
            .iter()
            .position(|i| i.name.eq_ignore_ascii_case(name))
    }

    /// Of `writes` (statements of instance `instance`'s block), the one
    /// that ran last in that instance's call, in a scan whose trace is
    /// `ran` (per step): the write whose line has the latest step of the
    /// call that ran (the body's order; of two writes on one line, the
    /// later). `None` when none of them ran, or there is no such instance.
    pub fn ran_last(&self, writes: &[StWrite], instance: &str, ran: &[bool]) -> Option<usize> {
        let owner = self.instance(instance)?;
        let steps = self.instances.get(owner)?.steps.clone();
        let line = steps
            .rev()
            .filter(|&s| self.owners.get(s).copied().flatten() == Some(owner))
            .filter(|&s| ran.get(s).copied().unwrap_or(false))
            .filter_map(|s| self.lines.get(s).copied().flatten())
            .find(|l| writes.iter().any(|w| w.line == *l))?;
        writes.iter().rposition(|w| w.line == line)
    }
}

impl StBlocks {
    /// Each step's ST line, for a program loaded from `loaded`: the
    /// ladder's IL followed by these blocks' `il` (none when `loaded`
    /// does not end with it: the blocks changed since).
    pub fn step_lines(&self, program: &Program, loaded: &str) -> Vec<Option<usize>> {
        let before = loaded.strip_suffix(self.il.as_str());
        let offset = match before {
            Some(b) if !self.il.is_empty() && (b.is_empty() || b.ends_with('\n')) => {
                b.lines().count()
            }
            _ => return vec![None; program.len()],
        };
        program
            .step_lines()
            .into_iter()
            .map(|line| {
                let n = line?.checked_sub(offset + 1)?;
                self.places.get(n).copied().filter(|&l| l > 0)
            })
            .collect()
    }
}

/// Each `FUNCTION_BLOCK` of ST `text`: its name as written and its lines,
/// from its `FUNCTION_BLOCK` to its `END_FUNCTION_BLOCK` (the text's end
/// when it has none). None when the text does not parse.
pub fn block_lines(text: &str) -> Vec<(String, RangeInclusive<usize>)> {
    let Ok(source) = parse_source(text) else {
        return Vec::new();
    };
    let lines: Vec<&str> = text.lines().collect();
    source
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Pou(p) if p.kind == PouKind::FunctionBlock => Some(p),
            _ => None,
        })
        .map(|p| {
            let first = (p.span.line as usize).max(1);
            let last = (first..=lines.len())
                .find(|&n| {
                    let word = lines[n - 1].split_whitespace().next().unwrap_or("");
                    word.eq_ignore_ascii_case("END_FUNCTION_BLOCK")
                })
                .unwrap_or(lines.len().max(first));
            (p.name.name.clone(), first..=last)
        })
        .collect()
}

#[cfg(test)]
mod tests;
