//! The ladder's zoom: buttons (out, in, fit the width, 100 %), Ctrl+wheel
//! (and a trackpad's pinch, which browsers send as Ctrl+wheel), and a
//! two-finger pinch on touch screens. The grid is drawn at 100 % and
//! scaled with CSS `zoom`, so every cell keeps its layout and hit area.

use leptos::prelude::*;

use super::LadderCtx;

/// The smallest and largest zoom.
pub const MIN: f64 = 0.4;
pub const MAX: f64 = 2.0;
/// One button press or wheel notch.
const STEP: f64 = 1.15;

/// `z` within [`MIN`, [`MAX`]], rounded to whole percents (1.0 for
/// anything that is not a number).
pub fn clamp(z: f64) -> f64 {
    if z.is_finite() {
        (z.clamp(MIN, MAX) * 100.0).round() / 100.0
    } else {
        1.0
    }
}

/// The zoom at which a drawing `natural` px wide (at 100 %) fits a box
/// `room` px wide; never above 100 %.
pub fn fit(room: f64, natural: f64) -> f64 {
    if natural <= 0.0 || room <= 0.0 {
        return 1.0;
    }
    clamp((room / natural).min(1.0))
}

/// One step in (`true`) or out, as the zoom buttons and the View menu do.
pub fn step(ctx: LadderCtx, zoom_in: bool) {
    ctx.panes.zoom.update(|z| {
        *z = clamp(if zoom_in { *z * STEP } else { *z / STEP });
    });
}

/// The zoom after a wheel notch with `delta_y` (up zooms in).
pub fn wheeled(z: f64, delta_y: f64) -> f64 {
    clamp(if delta_y < 0.0 { z * STEP } else { z / STEP })
}

/// Zooms so that a whole rung fits the ladder's box.
fn fit_width(ctx: LadderCtx, grid: NodeRef<leptos::html::Div>) {
    let Some(g) = grid.get_untracked() else {
        return;
    };
    let z = ctx.panes.zoom.get_untracked();
    let room = f64::from(g.client_width()) - 8.0;
    // The drawing's width at 100 %: what it takes now, unzoomed.
    let natural = f64::from(g.scroll_width()) / z;
    ctx.panes.zoom.set(fit(room, natural));
}

/// The zoom buttons.
#[component]
pub fn ZoomBar(ctx: LadderCtx, grid: NodeRef<leptos::html::Div>) -> impl IntoView {
    let t = move || ctx.page.lang.get().texts();
    view! {
        <span class="zoom-bar" role="group" aria-label=move || t().zoom>
            <button type="button" data-testid="zoom-out" title=move || t().zoom_out aria-label=move || t().zoom_out on:click=move |_| step(ctx, false)>"−"</button>
            <span class="zoom-at" data-testid="zoom-at">{move || format!("{:.0} %", ctx.panes.zoom.get() * 100.0)}</span>
            <button type="button" data-testid="zoom-in" title=move || t().zoom_in aria-label=move || t().zoom_in on:click=move |_| step(ctx, true)>"+"</button>
            <button type="button" data-testid="zoom-fit" on:click=move |_| fit_width(ctx, grid)>{move || t().zoom_fit}</button>
            <button type="button" data-testid="zoom-100" on:click=move |_| ctx.panes.zoom.set(1.0)>"100 %"</button>
        </span>
    }
}

/// Ctrl+wheel on the ladder zooms it (instead of the page).
pub fn on_wheel(ctx: LadderCtx, e: &web_sys::WheelEvent) {
    if e.ctrl_key() {
        e.prevent_default();
        ctx.panes.zoom.update(|z| *z = wheeled(*z, e.delta_y()));
    }
}

/// The pointers down on the ladder (touch only), by id, and the pinch.
#[derive(Clone, Copy)]
pub struct Touches {
    down: StoredValue<Vec<(i32, f64, f64)>>,
    /// With two fingers down: their distance when the second came down,
    /// and the zoom then.
    pinch: StoredValue<Option<(f64, f64)>>,
}

impl Touches {
    /// No finger down.
    pub fn new() -> Touches {
        Touches {
            down: StoredValue::new(Vec::new()),
            pinch: StoredValue::new(None),
        }
    }

    fn spread(&self) -> Option<f64> {
        self.down.with_value(|d| match d.as_slice() {
            [a, b] => Some(((a.1 - b.1).powi(2) + (a.2 - b.2).powi(2)).sqrt()),
            _ => None,
        })
    }

    /// A finger down (or moved, `moved`); with two, the zoom follows
    /// their spread.
    pub fn pointer(&self, ctx: LadderCtx, e: &web_sys::PointerEvent, moved: bool) {
        if e.pointer_type() != "touch" {
            return;
        }
        let (id, x, y) = (
            e.pointer_id(),
            f64::from(e.client_x()),
            f64::from(e.client_y()),
        );
        self.down
            .update_value(|d| match d.iter_mut().find(|p| p.0 == id) {
                Some(p) => *p = (id, x, y),
                None if !moved => d.push((id, x, y)),
                None => {}
            });
        let Some(spread) = self.spread() else {
            return;
        };
        match self.pinch.get_value() {
            None => self
                .pinch
                .set_value(Some((spread, ctx.panes.zoom.get_untracked()))),
            Some((from, z)) if from > 0.0 => ctx.panes.zoom.set(clamp(z * spread / from)),
            Some(_) => {}
        }
    }

    /// A finger up or cancelled: the pinch ends.
    pub fn up(&self, e: &web_sys::PointerEvent) {
        let id = e.pointer_id();
        self.down.update_value(|d| d.retain(|p| p.0 != id));
        self.pinch.set_value(None);
    }
}

impl Default for Touches {
    fn default() -> Self {
        Touches::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zoom_stays_within_its_range_and_fits_a_rung_in_its_box() {
        assert_eq!(clamp(5.0), MAX);
        assert_eq!(clamp(0.01), MIN);
        assert_eq!(clamp(f64::NAN), 1.0);
        assert_eq!(fit(600.0, 908.0), 0.66);
        assert_eq!(fit(1400.0, 908.0), 1.0, "never above 100 %");
        assert_eq!(fit(0.0, 908.0), 1.0);
        assert!(wheeled(1.0, -100.0) > 1.0 && wheeled(1.0, 100.0) < 1.0);
    }
}
