//! The command line's `--flag VALUE` pairs.

/// Parsed flags: each `--name value` (or `--name=value`) in order.
pub struct Args {
    pairs: Vec<(String, String)>,
}

impl Args {
    /// Parses `rest` (the words after the subcommand). Every flag takes a
    /// value; `allowed` lists the flags this subcommand knows.
    pub fn parse(rest: &[String], allowed: &[&str]) -> Result<Args, String> {
        let mut pairs = Vec::new();
        let mut words = rest.iter();
        while let Some(word) = words.next() {
            let Some(flag) = word.strip_prefix("--") else {
                return Err(format!("unexpected argument {}", engine::shown(word)));
            };
            let (name, value) = match flag.split_once('=') {
                Some((n, v)) => (n.to_string(), v.to_string()),
                None => {
                    let value = words
                        .next()
                        .ok_or_else(|| format!("--{flag} needs a value"))?;
                    (flag.to_string(), value.clone())
                }
            };
            if !allowed.contains(&name.as_str()) {
                return Err(format!(
                    "unknown option --{name} (this command takes {})",
                    allowed
                        .iter()
                        .map(|a| format!("--{a}"))
                        .collect::<Vec<_>>()
                        .join(" ")
                ));
            }
            pairs.push((name, value));
        }
        Ok(Args { pairs })
    }

    /// The value of a flag given at most once.
    pub fn optional(&self, name: &str) -> Result<Option<&str>, String> {
        let mut found = self.pairs.iter().filter(|(n, _)| n == name);
        let first = found.next().map(|(_, v)| v.as_str());
        if found.next().is_some() {
            return Err(format!("--{name} is given more than once"));
        }
        Ok(first)
    }

    /// The value of a flag that must be given once.
    pub fn required(&self, name: &str) -> Result<&str, String> {
        self.optional(name)?
            .ok_or_else(|| format!("--{name} is required"))
    }

    /// Every value of a repeatable flag, in order.
    pub fn all<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a str> + 'a {
        self.pairs
            .iter()
            .filter(move |(n, _)| n == name)
            .map(|(_, v)| v.as_str())
    }
}

impl Args {
    /// These flags without the values of `flag` that `drop` picks (the
    /// plant's `--set NAME.KEY=VALUE` taken out of the machine's).
    pub fn without(&self, flag: &str, drop: impl Fn(&str) -> bool) -> Args {
        let pairs = self
            .pairs
            .iter()
            .filter(|(n, v)| n != flag || !drop(v))
            .cloned()
            .collect();
        Args { pairs }
    }
}
