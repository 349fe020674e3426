//! A PLCopen import's warnings in Japanese (issue #49), made here from
//! their kinds as the errors are (`said_ja`). The command line's advice
//! (`--pou`) is left out, as the page's English leaves it out.

use engine::formats::plcopen::ImportWarning;

/// `w` in Japanese.
pub fn warning_ja(w: &ImportWarning) -> String {
    use ImportWarning as W;
    match w {
        W::WordOutputDropped(pin, expr) => format!(
            "ブロックの {pin} は変数 {} にだけつながっているので捨てました (Hashigo のラダーはワード出力を持ちません)",
            engine::shown(expr)
        ),
        W::VendorSkipped(what) => format!("{what} を飛ばしました: メーカー独自の要素です"),
        W::TakenAsBool(name) => {
            format!("{name} は宣言されていません: BOOL の変数としました")
        }
        W::AnalogRange {
            expr,
            register,
            input,
        } => format!(
            "{expr} は {register} ({input} のアナログ値) です: ファイルの単位で数えるよう {input} のアナログ範囲 ({input}A:n1:n2) を設定してください"
        ),
        W::DeclaredValue {
            what,
            pin,
            register,
            expr,
        } => format!(
            "{what} の {pin} は {register} で、{expr} の宣言の値を持ちます (プログラムは書き込みません)"
        ),
        W::Helper(relay, what) => {
            format!("{relay} に {what} を持たせました (ファイルが使わないリレー)")
        }
        W::StartsOff {
            name,
            value,
            machine,
            device,
        } => format!(
            "{name} はファイルでは {value} で始まりますが、{} は電源投入時に {device} をオフにします",
            machine_ja(machine)
        ),
        W::NoTask(kind, name) => {
            format!("{kind} {name} を飛ばしました: どのタスクも実行しません")
        }
        W::LeadsNowhere(leaf) => {
            format!("{leaf} はどのコイルにもつながらないので捨てました")
        }
    }
}

/// The engine's fallback "the machine" in Japanese; a machine's name is
/// kept (a product name).
fn machine_ja(machine: &str) -> &str {
    if machine == "the machine" {
        "このマシン"
    } else {
        machine
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_warning_is_said_in_japanese() {
        let s = || "X".to_string();
        let all = [
            ImportWarning::WordOutputDropped("ET".into(), s()),
            ImportWarning::VendorSkipped(s()),
            ImportWarning::TakenAsBool(s()),
            ImportWarning::AnalogRange {
                expr: s(),
                register: "D06".into(),
                input: "X04".into(),
            },
            ImportWarning::DeclaredValue {
                what: s(),
                pin: "IN2",
                register: "D10".into(),
                expr: s(),
            },
            ImportWarning::Helper("M55".into(), s()),
            ImportWarning::StartsOff {
                name: s(),
                value: "TRUE".into(),
                machine: "the machine".into(),
                device: "M00".into(),
            },
            ImportWarning::NoTask("program".into(), s()),
            ImportWarning::LeadsNowhere(s()),
        ];
        for w in &all {
            let ja = warning_ja(w);
            assert!(ja.chars().any(|c| c > '\u{3000}'), "{w:?}: {ja}");
            assert!(!ja.contains("the machine") && !ja.contains("--pou"), "{ja}");
        }
    }
}
