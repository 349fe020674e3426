//! One keyframe and the scans after it: a copy of the whole machine and a
//! count of scans; once asked for, each scan's end time and device image
//! (the first whole, then each scan's changed bytes), made by replay.

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
    /// Scans held (the keyframe's included).
    count: usize,
    /// Each scan's end time and image, for the first `images.filled`.
    times: Vec<SimTime>,
    images: Images,
}

/// Scans' images: the first whole, then each one's changes.
#[derive(Clone, Debug, Default)]
pub(super) struct Images {
    first: Vec<u8>,
    /// Every later scan's changes from the scan before, back to back:
    /// (offset, byte).
    changes: Vec<(u16, u8)>,
    /// Where each later scan's changes end in `changes`.
    ends: Vec<u32>,
    /// How many scans' images are held (0: none yet).
    filled: usize,
}

/// Per held image beyond its changes: its time, where its changes end.
const PER_IMAGE: usize = std::mem::size_of::<SimTime>() + std::mem::size_of::<u32>();

impl<M> Chunk<M> {
    pub fn new(first: u64, machine: M, ops_at: u64) -> Chunk<M> {
        Chunk {
            first,
            machine,
            ops_at,
            count: 1,
            times: Vec::new(),
            images: Images::default(),
        }
    }

    /// Scans held.
    pub fn len(&self) -> usize {
        self.count
    }

    /// The mark of its last scan.
    pub fn last(&self) -> u64 {
        self.first + self.len() as u64 - 1
    }

    /// Its memory, estimated, with `machine_bytes` for the copy.
    pub fn bytes(&self, machine_bytes: usize) -> usize {
        machine_bytes + self.images.bytes()
    }

    /// Counts a scan.
    pub fn push(&mut self) {
        self.count += 1;
    }

    /// Counts `n` scans.
    pub fn push_many(&mut self, n: u64) {
        self.count = self
            .count
            .saturating_add(usize::try_from(n).unwrap_or(usize::MAX));
    }

    /// Keeps the first `keep` scans; the bytes freed.
    pub fn truncate(&mut self, keep: usize) -> usize {
        let keep = keep.max(1);
        let before = self.images.bytes();
        self.count = self.count.min(keep);
        self.times.truncate(keep);
        self.images.truncate(keep);
        before - self.images.bytes()
    }

    /// Whether every scan's time and image are held.
    pub fn filled(&self) -> bool {
        self.images.filled >= self.len()
    }

    /// The end time of scan `i`, if held.
    pub fn time(&self, i: usize) -> Option<SimTime> {
        self.times.get(i).copied()
    }

    /// The held scans' end times.
    pub fn times(&self) -> &[SimTime] {
        &self.times
    }

    /// Replaces the times and images with `shots` (one per scan from the
    /// first, in order); the bytes held (new, old).
    pub fn fill<'a>(&mut self, shots: impl Iterator<Item = (&'a [u8], SimTime)>) -> (usize, usize) {
        let old = self.images.bytes();
        let mut held = Images::default();
        let mut times = Vec::with_capacity(self.count);
        let mut before: Vec<u8> = Vec::new();
        for (image, time) in shots.take(self.count) {
            if held.filled == 0 {
                held.first = image.to_vec();
            } else {
                held.push(&before, image);
            }
            times.push(time);
            before.clear();
            before.extend_from_slice(image);
            held.filled += 1;
        }
        self.images = held;
        self.times = times;
        (self.images.bytes(), old)
    }

    /// The image at scan `i` of this chunk, into `image`; false if not held.
    pub fn image_at(&self, i: usize, image: &mut Vec<u8>) -> bool {
        if i >= self.images.filled {
            return false;
        }
        image.clear();
        image.extend_from_slice(&self.images.first);
        for k in 1..=i {
            apply(image, self.images.changes_of(k));
        }
        true
    }

    /// Calls `f` with each held scan's index and image, in order.
    pub fn each_image(&self, image: &mut Vec<u8>, mut f: impl FnMut(usize, &[u8])) {
        if self.images.filled == 0 {
            return;
        }
        image.clear();
        image.extend_from_slice(&self.images.first);
        f(0, image);
        for k in 1..self.images.filled {
            apply(image, self.images.changes_of(k));
            f(k, image);
        }
    }
}

impl Images {
    fn bytes(&self) -> usize {
        self.first.len()
            + PER_IMAGE * self.ends.len()
            + std::mem::size_of::<(u16, u8)>() * self.changes.len()
    }

    /// Adds a scan whose image is `now` after `before`.
    fn push(&mut self, before: &[u8], now: &[u8]) {
        // Most scans change nothing: one comparison of the whole image.
        // One machine's images all have one length (its layout).
        if before != now {
            let changed = now
                .iter()
                .zip(before)
                .enumerate()
                .filter(|(_, (n, b))| n != b)
                .filter_map(|(i, (&n, _))| Some((u16::try_from(i).ok()?, n)));
            self.changes.extend(changed);
        }
        self.ends
            .push(u32::try_from(self.changes.len()).unwrap_or(u32::MAX));
    }

    /// Keeps the first `keep` scans' images.
    fn truncate(&mut self, keep: usize) {
        if self.filled <= keep {
            return;
        }
        self.filled = keep;
        self.ends.truncate(keep.saturating_sub(1));
        let end = self.ends.last().map_or(0, |&e| e as usize);
        self.changes.truncate(end);
        if keep == 0 {
            self.first.clear();
        }
    }

    /// Scan `i`'s changes (for `i` ≥ 1).
    fn changes_of(&self, i: usize) -> &[(u16, u8)] {
        let start = if i >= 2 { self.ends[i - 2] as usize } else { 0 };
        let end = self.ends[i - 1] as usize;
        &self.changes[start..end]
    }
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
