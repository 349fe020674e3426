//! A serial console: what the device sent, and a line to type at it. The
//! IO86A terminal and the Arduino serial monitor both use it.

use leptos::ev;
use leptos::prelude::*;

/// The most output kept on screen.
const SCROLLBACK: usize = 20_000;

/// Appends what a device sent as it sent it (a CR LF may come in two
/// pieces), keeping the last [`SCROLLBACK`] bytes.
pub fn append(console: RwSignal<String>, sent: &str) {
    console.update(|c| {
        c.push_str(sent);
        if c.len() > SCROLLBACK {
            let cut = c.len() - SCROLLBACK;
            let cut = (cut..c.len())
                .find(|&i| c.is_char_boundary(i))
                .unwrap_or(cut);
            c.drain(..cut);
        }
    });
}

/// The console pane. `testid` names the output (`{testid}`) and the input
/// line (`{testid}-input`); `ctrl_c`, when given, adds a Ctrl-C button and
/// sends Ctrl-C for the key in the input line.
#[component]
pub fn ConsolePane(
    title: Signal<String>,
    hint: Signal<String>,
    testid: &'static str,
    console: RwSignal<String>,
    /// Called with each line typed.
    on_line: Callback<String>,
    #[prop(optional)] ctrl_c: Option<(Signal<String>, Callback<()>)>,
) -> impl IntoView {
    let input = RwSignal::new(String::new());
    view! {
        <section class="terminal">
            <h2>{move || title.get()}</h2>
            <pre data-testid=testid aria-live="polite" tabindex="0">
                // CR LF, and a CR alone, are line ends: a page cannot
                // overwrite a line as a terminal does.
                {move || console.with(|c| c.replace("\r\n", "\n").replace('\r', "\n"))}
            </pre>
            <div class="terminal-input">
                <input
                    type="text"
                    data-testid=format!("{testid}-input")
                    spellcheck="false"
                    autocomplete="off"
                    placeholder=move || hint.get()
                    aria-label=move || title.get()
                    prop:value=move || input.get()
                    on:input=move |e| input.set(event_target_value(&e))
                    on:keydown=move |e: ev::KeyboardEvent| {
                        if e.key() == "Enter" {
                            on_line.run(input.get_untracked());
                            input.set(String::new());
                        } else if let (Some((_, send)), true, "c") = (ctrl_c, e.ctrl_key(), e.key().as_str()) {
                            e.prevent_default();
                            send.run(());
                        }
                    }
                />
                {ctrl_c
                    .map(|(label, send)| {
                        view! {
                            <button type="button" data-testid=format!("{testid}-ctrl-c") on:click=move |_| send.run(())>
                                {move || label.get()}
                            </button>
                        }
                    })}
            </div>
        </section>
    }
}
