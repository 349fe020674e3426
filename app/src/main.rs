//! The page's entry point: mount the app on the body.

fn main() {
    app::start();
}
