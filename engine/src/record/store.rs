//! One keyframe and the scans after it: a whole image and machine copy,
//! then each scan's changed bytes.

use crate::time::SimTime;

/// A keyframe's scans.
#[derive(Clone, Debug)]
pub(super) struct Chunk<M> {
    /// The mark of its first scan (the keyframe's).
    pub first: u64,
    /// The whole machine at its first scan.
    pub machine: M,
    /// The absolute index of the first op logged after its first scan.
    pub ops_at: u64,
    /// The whole image at its first scan.
    image: Box<[u8]>,
    /// Each later scan's changes from the scan before: (offset, byte).
    changes: Vec<Box<[(u16, u8)]>>,
    /// Each scan's end time (the first's included).
    pub times: Vec<SimTime>,
}

/// Bookkeeping per scan beyond its changes: time, box.
const PER_SCAN: usize = std::mem::size_of::<SimTime>() + std::mem::size_of::<Box<[(u16, u8)]>>();

impl<M> Chunk<M> {
    pub fn new(first: u64, machine: M, ops_at: u64, image: &[u8], time: SimTime) -> Chunk<M> {
        Chunk {
            first,
            machine,
            ops_at,
            image: image.into(),
            changes: Vec::new(),
            times: vec![time],
        }
    }

    /// Scans held.
    pub fn len(&self) -> usize {
        self.times.len()
    }

    /// Its memory, estimated, with `machine_bytes` for the copy.
    pub fn bytes(&self, machine_bytes: usize) -> usize {
        let changes: usize = self.changes.iter().map(|c| change_bytes(c.len())).sum();
        machine_bytes + self.image.len() + PER_SCAN * self.len() + changes
    }

    /// Adds a scan whose image is `now` after `before`; the bytes it took.
    pub fn push(&mut self, before: &[u8], now: &[u8], time: SimTime) -> usize {
        // One machine's images all have one length (its layout).
        let changed: Vec<(u16, u8)> = now
            .iter()
            .enumerate()
            .filter(|&(i, b)| before.get(i) != Some(b))
            .filter_map(|(i, &b)| Some((u16::try_from(i).ok()?, b)))
            .collect();
        let n = changed.len();
        self.changes.push(changed.into_boxed_slice());
        self.times.push(time);
        PER_SCAN + change_bytes(n)
    }

    /// Keeps the first `keep` scans; the bytes freed.
    pub fn truncate(&mut self, keep: usize) -> usize {
        let keep = keep.max(1);
        let freed: usize = self
            .changes
            .iter()
            .skip(keep - 1)
            .map(|c| PER_SCAN + change_bytes(c.len()))
            .sum();
        self.changes.truncate(keep - 1);
        self.times.truncate(keep);
        freed
    }

    /// The image at scan `i` of this chunk, into `image`.
    pub fn image_at(&self, i: usize, image: &mut Vec<u8>) {
        image.clear();
        image.extend_from_slice(&self.image);
        for c in self.changes.iter().take(i) {
            apply(image, c);
        }
    }

    /// Calls `f` with each scan's index and image, in order.
    pub fn each_image(&self, image: &mut Vec<u8>, mut f: impl FnMut(usize, &[u8])) {
        image.clear();
        image.extend_from_slice(&self.image);
        f(0, image);
        for (i, c) in self.changes.iter().enumerate() {
            apply(image, c);
            f(i + 1, image);
        }
    }
}

fn change_bytes(n: usize) -> usize {
    n * std::mem::size_of::<(u16, u8)>()
}

fn apply(image: &mut Vec<u8>, changes: &[(u16, u8)]) {
    for &(at, b) in changes {
        let at = usize::from(at);
        if image.len() <= at {
            image.resize(at + 1, 0);
        }
        image[at] = b;
    }
}
