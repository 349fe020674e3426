//! A project file and a share link hold the plant, its wiring,
//! parameters and faults (version 4 files, `5.` links); links made before
//! plants (versions 1-4) still open and are made again byte for byte.

use engine::formats::project::{PlantSetup, Project};
use engine::formats::share::{decode, encode};

use super::common::{hashigo, text, Temp};

/// Links made by Hashigo before plants (issue #50), one of each version:
/// MINASEC-U's seed program as text (1.), with its tests (2.), the soft
/// PLC's tank (variables: 3.), the conveyor exercise with its task (4.).
const OLD_LINKS: [&str; 4] = [
    "1.JUzBDYBADEKInYe6Qjcwfej-i9g724QAAQCcoKjH1kCGXvvgRsxrU7Ez2AY41x6eRLD-0Hjl1UwsMTtXqHzjAw",
    "2.lVNNb9NAEHXs2pVa0RaEOACV5gaHdDW7bRpaxAVL_ADwAY5WusarOnbk2YL498zsOhRKe2gO0cybjzfv2U6ytMRUY1rhjlaa0kqnmvLsK2JOvh49R3qH_LDhwOyvhpvew6qz9Zh9Q9wdb_re9d851k9ibbT1qrVX-dsvMg28Zw4yzpG-BJ6BduiuCJwn2zUw9GmWClsmRIUsnaXhP5mpT51bXdsRfrauszBxXUKFEtMEVxocwdA0sywMZiyhYDnJCVe8W1vigTfc0Z9I9h7kwLDDkYVwNAF7wL8KC9GfFOwJ8z8rg6J17UURdPV6M-OuEuVMneyXt2YwLv4UWYmfkySP1r1AtaC5OKD3UC1jiHvZobjwARBqD6jO6JXkcg1Lcr51fUCVQnVOr6XG234RaGjGYQ2yCfwABmm3iQY9RPSyurNXc59Smluk1NRd96dkQsmod_Tf1CnfodSpuqDp-TO7xgdIi4MS1Q-Wp0WeocMpvQgp0gFbtxXP6dG2OwJmW9dTehzqkwEYHTA6GnBGz8ObdW3thpF2eprz-w8zAdQMmoUyMWaPgvn_OhGMWPDHcHxr_pZa4EC-vHv6OeXhVfj4GHoT6kbQZUQNo-nTaXXcvGTOo79tk9bf",
    "3.PY7BCsIwEESnaaxXEQSPAelNykb_wFugtAgBvYlIagJBD5b0901S8bTD8HizHGAo2Ja1GqxUnVx4E4yP6bBUnd4diVDxm39PESxZTiW37mkrPjjvCzYfFMDc81Pft1WtrtRIbEZrRGpF1orP5MaHxX9E81pdCOuE5W4vqGkkxdXs_cnOUUZYJcq9hviCCHcfDL4",
    "4.dVTdbtRGFPbaKBc8ASpVde6aWIllq6WqIlGpN22lqq3UplJzZ8POsla9MyvPmCh3GbsRUBKhggpKWkEVClkIJEIIkMLvC_AUw-6yb8GZsddZBNysds75zne--c4ZWw17IbADbh2yGrbt_Ob7UxiwrIZjOz_4voORYAr_6ZDJm5NvWbZjI9DRqSln0fcbtvm1Gg0HlqJYcGCUACcnGW3CCdJiKZ5ElIqYnrKcjzF8miyz1Itpi5AmHIcAIgHHfL_Dj9TJDhMsxZyvcwH_6J2EKQq8Y_xokyTxaZJy6GIPDtgPIujENBPEsj-pCysYdvzqOHypq7_wJ3ijJEo7fNwRU0coAxOEmEILSytObtlHP1D1me9zeH_Dz2uA9cJx3YU2gROM_f7pBN514WtzB-hmAj0EoUEkESCylHJzrDwjywRCnFiIMA9-0ebWaKQsPQoXNcB1J6aRRIKkrjtfz0OLYvQkEnNoRvQUSVlWWqjp2hHWiHZUKtKRbtUpJR58T0j3QGOaUaoJMyriBAdgkO2IQ0JaAvRWECTrRrwkYpmYvEkQzuowRWGsi2jv8OE5-JUTgxVxh-B1FoIQpjnBeobT5zO1TDQ6Wvaw4OeMwlIs2qXUJKICwrG9WNskrShDqUtxikrnISzd1CaWbs5CWOkax7Su0NhZRrSlM97LQ647-PeOkruq2FDFjirOqvy-Ku7rY76lVnKc5ajo9S9JlV88wMid10_OKfmPys8r2euv3uhfuK5J8se6Nn-giifVWJVc--lHxCt5W-V_KvlMyQ2kfauL7r6FJSp_bgoXy8I91w2G2xf7z9ZcFxn65_9WEttdUfKmkheU_E9JjPyBbJUYeW149c7o8qUxeL1_Zl-3kz21ImvM4BySrPXX72lJWI6cOaa2S2HVZRFwZv_9l8LhoRejlU0lr2spB6bsDnf2SjrdWFuDt92udQ8fYslfKMXIuoawwd0tlcvaFL0qI7mq8jVj2J72I_9fFVdNZ9yaae2HNr93t7-7OYMyXj19bu4wZpgDVVxRxS1j7tnJpZlUUuKnB72Nwf5l1D1aXR8-2pzYI2xezg_VHmxSFQ1MtNolEzPLhO2tb99-wdBKWQcWglmgrDog6TxGqi8BbuLEo45a-Kg1wvvmO5Y0DU35BUAcPpikNdfWcfMysOfMB96oeZuo07PeAA",
];

const CONVEYOR: &str = include_str!("../../programs/minasec-u/conveyor.json");

fn with_plant() -> Project {
    let mut p = Project::from_json(CONVEYOR).expect("reads");
    p.plant = Some(PlantSetup {
        name: "conveyor".into(),
        wiring: Some(vec![
            ["infeed".into(), "X05".into()],
            ["motor".into(), "Y03".into()],
        ]),
        params: [("speed".to_string(), "500".to_string())].into(),
        faults: vec!["motor dead from 20s".into()],
    });
    p
}

#[test]
fn links_made_before_plants_open_and_are_made_again_byte_for_byte() {
    for (i, link) in OLD_LINKS.iter().enumerate() {
        assert!(link.starts_with(&format!("{}.", i + 1)));
        let p = decode(link).expect("opens");
        assert_eq!(p.plant, None);
        assert_eq!(encode(&p).expect("encodes"), *link, "version {}", i + 1);
        assert!(p.needed_version() <= 3);
    }
}

#[test]
fn a_plant_travels_in_the_project_file_and_a_version_5_link() {
    let p = with_plant();
    let json = p.to_json();
    assert!(json.contains("\"version\": 4"), "{json}");
    let back = Project::from_json(&json).expect("reads");
    assert_eq!(
        back,
        Project {
            version: 4,
            ..p.clone()
        }
    );
    let link = encode(&p).expect("encodes");
    assert!(link.starts_with("5."), "{link:.10}");
    let opened = decode(&link).expect("opens");
    assert_eq!(opened.plant, p.plant);
    assert_eq!(opened.exercise, p.exercise);
    assert_eq!(opened.tests, p.tests);
    // The default wiring (no wiring at all) is not an empty one.
    let mut default = p.clone();
    default.plant.as_mut().unwrap().wiring = None;
    assert_eq!(
        decode(&encode(&default).unwrap())
            .unwrap()
            .plant
            .unwrap()
            .wiring,
        None
    );
    // A damaged plant section is an error, never a panic.
    let mut cut = link.clone();
    cut.truncate(link.len() - 6);
    assert!(decode(&cut).is_err());
}

#[test]
fn a_project_s_plant_runs_without_plant_options_and_the_options_override_it() {
    let tmp = Temp::new("plant-project");
    let mut p = with_plant();
    p.plant.as_mut().unwrap().wiring = None;
    p.plant.as_mut().unwrap().faults.clear();
    let file = tmp.file("conveyor.json", &p.to_json());
    let run = |extra: &[&str]| {
        let args = [
            &[
                "run",
                "--program",
                &file,
                "--until",
                "60s",
                "--watch",
                "conveyor.delivered",
            ][..],
            extra,
        ]
        .concat();
        let out = hashigo(&args, "");
        (out.status.code(), text(&out.stdout), text(&out.stderr))
    };
    let (code, held, err) = run(&[]);
    assert_eq!(code, Some(0), "{err}");
    let delivered = |csv: &str| -> i64 {
        csv.lines()
            .last()
            .unwrap()
            .split(',')
            .nth(1)
            .unwrap()
            .parse()
            .unwrap()
    };
    // The project's speed of 500 mm/s delivers more than the default's.
    let (_, plain, _) = run(&["--plant", "conveyor"]);
    assert!(delivered(&held) > delivered(&plain), "{held} {plain}");
    let (_, dead, _) = run(&["--fault", "motor dead"]);
    assert_eq!(delivered(&dead), 0);
    // Its mistakes name the file.
    let mut bad = p.clone();
    bad.plant.as_mut().unwrap().faults = vec!["belt dead".into()];
    bad.plant.as_mut().unwrap().wiring = Some(vec![["level".into(), "X02".into()]]);
    let file = tmp.file("bad.json", &bad.to_json());
    let out = hashigo(&["test", "--program", &file], "");
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("bad.json: plant fault \"belt dead\": conveyor has no signal \"belt\""),
        "{err}"
    );
    let out = hashigo(&["test", "--program", &file, "--fault", "motor dead"], "");
    assert!(
        text(&out.stderr).contains("bad.json: plant fault"),
        "project faults are checked even with --fault"
    );
    let mut bad = p;
    bad.plant.as_mut().unwrap().wiring = Some(vec![["belt".into(), "X02".into()]]);
    let file = tmp.file("bad2.json", &bad.to_json());
    let out = hashigo(&["test", "--program", &file], "");
    let err = text(&out.stderr);
    assert!(
        err.contains("bad2.json: plant wiring entry 1: conveyor has no signal \"belt\""),
        "{err}"
    );
}
