//! Reading projects and clipboard cells (the engine's JSON readers, with
//! serde's machinery for the ladder's elements) is a part of its own
//! (issue #53, docs/performance.md "Parts"): a first visit has nothing
//! to read. A returning visit reads its saved ladders before the page
//! starts ([`read_saved`], the loading screen still up); a file opened,
//! a clipboard pasted or another tab's save is read when it comes.

use std::cell::RefCell;
use std::collections::HashMap;

use engine::formats::project::{Project, ProjectError};
use engine::ladder::edit::{Clip, ClipError};
use engine::Located;

use crate::parts::PartMissing;

crate::parts::part_fn!(
    reading,
    /// A project file's or a save's text read.
    pub(crate) fn project(
        text: String,
    ) -> Result<Result<Project, Located<ProjectError>>, PartMissing> {
        Ok(Project::from_json(&text))
    }
);

crate::parts::part_fn!(
    reading,
    /// Cells on the clipboard read.
    pub(crate) fn clip(text: String) -> Result<Result<Clip, ClipError>, PartMissing> {
        Ok(Clip::from_text(&text))
    }
);

crate::parts::part_fn!(
    reading,
    /// Saved texts read, each under its key: `None` where one does not
    /// read as a project.
    fn projects(
        saved: Vec<(String, String)>,
    ) -> Result<Vec<(String, Option<Project>)>, PartMissing> {
        Ok(saved
            .into_iter()
            .map(|(key, text)| {
                let project = Project::from_json(&text).ok();
                (key, project)
            })
            .collect())
    }
);

thread_local! {
    /// The saved ladders read before the page started, by key, until the
    /// editors take them ([`take`]).
    static READ: RefCell<HashMap<String, Option<Project>>> = RefCell::new(HashMap::new());
}

/// Reads the saved texts `saved` (key, text) before the page starts:
/// the editors then restore them synchronously ([`take`]).
pub async fn read_saved(saved: Vec<(String, String)>) -> Result<(), PartMissing> {
    let read = projects(saved).await?;
    READ.with(|r| r.borrow_mut().extend(read));
    Ok(())
}

/// What [`read_saved`] read under `key`: `None` when nothing was read
/// there; `Some(None)` when it did not read as a project.
pub fn take(key: &str) -> Option<Option<Project>> {
    READ.with(|r| r.borrow_mut().remove(key))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs a future that does not wait (a part's function without the
    /// split: an `async fn` that returns at once).
    fn now<F: std::future::Future>(f: F) -> F::Output {
        let mut f = std::pin::pin!(f);
        let mut cx = std::task::Context::from_waker(std::task::Waker::noop());
        match f.as_mut().poll(&mut cx) {
            std::task::Poll::Ready(out) => out,
            std::task::Poll::Pending => panic!("the reader waited"),
        }
    }

    #[test]
    fn saved_texts_read_before_the_start_are_taken_once_each() {
        let good = Project::new(engine::MachineId::Io86a, engine::ladder::Ladder::default());
        let saved = vec![
            ("k.good".to_string(), good.to_json()),
            ("k.bad".to_string(), "{\"format\": \"nope\"}".to_string()),
        ];
        now(read_saved(saved)).expect("no part to fetch natively");
        let read = take("k.good").expect("read").expect("a project");
        assert_eq!(read.machine, engine::MachineId::Io86a);
        assert!(take("k.good").is_none(), "taken once");
        assert!(
            matches!(take("k.bad"), Some(None)),
            "did not read: kept aside by the caller"
        );
        assert!(take("k.never").is_none());
    }

    #[test]
    fn a_file_and_the_clipboard_are_read_with_the_engines_errors() {
        let e = now(project("{".to_string()))
            .expect("no part")
            .expect_err("not JSON");
        assert_eq!(e.line, 1);
        let clip = now(clip("not cells".to_string())).expect("no part");
        assert!(clip.is_err());
    }
}
