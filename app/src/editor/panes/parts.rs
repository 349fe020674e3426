//! The tools' panes held in parts (issue #53, docs/performance.md
//! "Parts"): each is fetched when its tab (or sheet) is first shown, not
//! by the first screen; each part function hands back the function that
//! draws its pane from what the page gives it.

use leptos::prelude::*;

use super::{cases, chart, find, projects, side, variables, why};
use crate::editor::LadderCtx;

crate::parts::part_fn!(
    pane_chart,
    /// The timing chart is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn chart() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing> {
        Ok(|ctx| view! { <chart::TimingChart ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    pane_tests,
    /// The Tests pane (and an exercise's task) is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn tests() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing> {
        Ok(|ctx| view! { <cases::TestsPane ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    pane_find,
    /// Find and replace is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn find(
    ) -> Result<crate::parts::DrawFor<(LadderCtx, Callback<()>)>, crate::parts::PartMissing> {
        Ok(|(ctx, on_pick)| view! { <find::FindPane ctx on_pick /> }.into_any())
    }
);

crate::parts::part_fn!(
    pane_projects,
    /// The projects list is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn projects() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing>
    {
        Ok(|ctx| view! { <projects::ProjectsPane ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    pane_listing,
    /// The listing and problems is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn listing(
    ) -> Result<crate::parts::DrawFor<(LadderCtx, Callback<()>)>, crate::parts::PartMissing> {
        Ok(|(ctx, on_pick)| {
            view! {
                <div class="dock-pair">
                    <side::ListingPane ctx on_pick />
                    <side::ProblemsPane ctx on_pick />
                </div>
            }
            .into_any()
        })
    }
);

crate::parts::part_fn!(
    pane_variables,
    /// The variables pane (the soft PLC's) is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn variables() -> Result<crate::parts::DrawFor<LadderCtx>, crate::parts::PartMissing>
    {
        Ok(|ctx| view! { <variables::VariablesPane ctx /> }.into_any())
    }
);

crate::parts::part_fn!(
    pane_why,
    /// The Why? pane is a part of its own (issue #53): fetched when first shown,
    /// not by the first screen.
    pub(crate) fn why(
    ) -> Result<crate::parts::DrawFor<(LadderCtx, Callback<()>)>, crate::parts::PartMissing> {
        Ok(|(ctx, on_back)| view! { <why::WhyPanel ctx on_back /> }.into_any())
    }
);
