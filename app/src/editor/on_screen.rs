//! Which rungs are on screen, for a running frame to bring those up to
//! date every frame and the others in turn (`RungView::due`): the
//! browser's intersection observer says so when a rung comes into or
//! leaves the ladder's view (its margin: half a view above and below),
//! so no frame measures the page (a forced layout of every cell).

use leptos::prelude::*;
use leptos::wasm_bindgen::closure::Closure;
use leptos::wasm_bindgen::JsCast;

use super::state::LadderCtx;

type Callback = Closure<dyn FnMut(js_sys::Array)>;

/// The grid's observer of its rungs, made when the first rung is shown.
#[derive(Clone, Copy)]
pub struct OnScreen {
    ctx: LadderCtx,
    grid: NodeRef<leptos::html::Div>,
    observer: StoredValue<Option<(web_sys::IntersectionObserver, Callback)>, LocalStorage>,
}

impl OnScreen {
    /// An observer of `grid`'s rungs (none made yet).
    pub fn new(ctx: LadderCtx, grid: NodeRef<leptos::html::Div>) -> OnScreen {
        let observer = StoredValue::new_local(None);
        on_cleanup(move || {
            observer.try_with_value(|o: &Option<(web_sys::IntersectionObserver, Callback)>| {
                if let Some((o, _)) = o {
                    o.disconnect();
                }
            });
        });
        OnScreen {
            ctx,
            grid,
            observer,
        }
    }

    /// Watches rung element `rung` (its `data-rid` the rung's id).
    pub fn watch(self, rung: &web_sys::Element) {
        if self.observer.with_value(Option::is_none) {
            let made = self.make();
            self.observer.set_value(made);
        }
        self.observer.with_value(|o| {
            if let Some((o, _)) = o {
                o.observe(rung);
            }
        });
    }

    /// Stops watching `rung` (it left the ladder).
    pub fn unwatch(self, rung: &web_sys::Element) {
        self.observer.try_with_value(|o| {
            if let Some((o, _)) = o {
                o.unobserve(rung);
            }
        });
    }

    fn make(self) -> Option<(web_sys::IntersectionObserver, Callback)> {
        let ctx = self.ctx;
        let callback: Callback = Closure::new(move |entries: js_sys::Array| {
            let Some(rungs) = ctx.drawing.rungs.try_get_untracked() else {
                return;
            };
            for entry in entries.iter() {
                let entry: web_sys::IntersectionObserverEntry = entry.unchecked_into();
                let id = entry.target().get_attribute("data-rid");
                let Some(id) = id.and_then(|id| id.parse::<u64>().ok()) else {
                    continue;
                };
                if let Some(rung) = rungs.iter().find(|r| r.id == id) {
                    rung.set_seen(entry.is_intersecting());
                }
            }
        });
        let options = web_sys::IntersectionObserverInit::new();
        // The ladder scrolls in its own box (else the page's view).
        if let Some(grid) = self.grid.get_untracked() {
            let grid: &web_sys::Element = &grid;
            options.set_root(Some(grid));
        }
        options.set_root_margin("50% 0px");
        let observer = web_sys::IntersectionObserver::new_with_options(
            callback.as_ref().unchecked_ref(),
            &options,
        );
        observer.ok().map(|o| (o, callback))
    }
}
