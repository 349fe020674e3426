//! The words of the parts fetched on first use (issue #53): what shows
//! while a part loads, and where it could not be fetched.

/// The strings of a part's place while it loads or after it failed.
pub struct PartsTexts {
    pub loading: &'static str,
    pub missing: &'static str,
    pub retry: &'static str,
}

/// English.
pub static EN: PartsTexts = PartsTexts {
    loading: "Loading this part of the page…",
    missing:
        "This part of the page could not be fetched (offline on a first visit?). Your work is kept.",
    retry: "Try again",
};

/// Japanese.
pub static JA: PartsTexts = PartsTexts {
    loading: "この部分を読み込んでいます…",
    missing: "この部分を取得できませんでした（初回の訪問でオフラインかもしれません）。作業内容はそのまま残っています。",
    retry: "再試行",
};
