//! bench-256.st computes what bench-256.il computes, in no more steps
//! (the scan runs the same instructions: ST is as fast as that IL).

use engine::softplc::Program;

const IL: &str = include_str!("../../programs/soft-plc/bench-256.il");
const ST: &str = include_str!("../../programs/soft-plc/bench-256.st");

#[test]
fn bench_256_in_st_equals_the_il_in_values_and_steps() {
    let mut il = Program::load(IL).expect("the IL loads");
    let mut st = Program::load_st(ST).expect("the ST loads");
    assert!(
        st.len() <= il.len(),
        "ST {} steps, IL {}",
        st.len(),
        il.len()
    );
    for scan in 0..300 {
        il.scan(scan);
        st.scan(scan);
        for i in 0..256 {
            for name in [format!("m{i}"), format!("w{i}")] {
                assert_eq!(il.value(&name), st.value(&name), "{name} at scan {scan}");
            }
        }
    }
}
