//! The mesh builder's index of corners: a 64-bit fingerprint of each corner → the first vertex
//! with that fingerprint, in 8 bytes a slot (a 32-bit tag of the fingerprint and the vertex),
//! half what a `HashMap<u64, u32>` takes, because it is the largest thing a big load holds
//! besides the mesh. Open addressing with linear probing, at most 3/4 full.

/// An empty slot.
const EMPTY: u64 = u64::MAX;

#[derive(Default)]
pub(crate) struct CornerIndex {
    slots: Vec<u64>,
    len: usize,
}

impl CornerIndex {
    /// An index that holds `len` entries without growing.
    pub(crate) fn with_capacity(len: usize) -> Self {
        let slots = (len.saturating_mul(4) / 3 + 1)
            .next_power_of_two()
            .max(1024);
        Self {
            slots: vec![EMPTY; slots],
            len: 0,
        }
    }

    /// The vertex that holds `fingerprint`, if any. `has_fingerprint` says whether a vertex
    /// whose slot has the fingerprint's tag has the whole fingerprint.
    pub(crate) fn get(
        &self,
        fingerprint: u64,
        has_fingerprint: impl Fn(u32) -> bool,
    ) -> Option<u32> {
        if self.slots.is_empty() {
            return None;
        }
        let mask = self.slots.len() - 1;
        let mut at = self.home(tag(fingerprint));
        loop {
            let slot = self.slots[at];
            if slot == EMPTY {
                return None;
            }
            let vertex = slot as u32;
            if slot >> 32 == tag(fingerprint) && has_fingerprint(vertex) {
                return Some(vertex);
            }
            at = (at + 1) & mask;
        }
    }

    /// Records `vertex` for `fingerprint`, which [`CornerIndex::get`] has just not found.
    pub(crate) fn insert(&mut self, fingerprint: u64, vertex: u32) {
        if 4 * (self.len + 1) > 3 * self.slots.len() {
            self.grow();
        }
        let at = self.free_slot(tag(fingerprint));
        self.slots[at] = tag(fingerprint) << 32 | u64::from(vertex);
        self.len += 1;
    }

    /// The slot where the search for a fingerprint with tag `tag` starts: the tag mixed once
    /// more (Fibonacci hashing), top bits first. From the tag alone, so that growing needs only
    /// the slots.
    fn home(&self, tag: u64) -> usize {
        let bits = self.slots.len().trailing_zeros();
        (tag.wrapping_mul(0x9e37_79b9_7f4a_7c15) >> (64 - bits)) as usize
    }

    /// Twice the slots (at least 1024), every entry placed again.
    fn grow(&mut self) {
        let slots = (2 * self.slots.len()).max(1024);
        let old = std::mem::replace(&mut self.slots, vec![EMPTY; slots]);
        for slot in old.into_iter().filter(|&s| s != EMPTY) {
            let at = self.free_slot(slot >> 32);
            self.slots[at] = slot;
        }
    }

    /// The first empty slot from the home of `tag` on.
    fn free_slot(&self, tag: u64) -> usize {
        let mask = self.slots.len() - 1;
        let mut at = self.home(tag);
        while self.slots[at] != EMPTY {
            at = (at + 1) & mask;
        }
        at
    }
}

/// The fingerprint's top 32 bits, never all ones so that no slot equals [`EMPTY`].
fn tag(fingerprint: u64) -> u64 {
    (fingerprint >> 32).min(u64::from(u32::MAX - 1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::collections::HashMap;

    /// Vertex `i` has fingerprint `fingerprints[i]`; returns the index's answer for each, first
    /// inserting those it does not find, as the mesh builder does.
    fn index_all(fingerprints: &[u64]) -> Vec<Option<u32>> {
        let mut index = CornerIndex::default();
        let mut answers = Vec::new();
        for (i, &f) in fingerprints.iter().enumerate() {
            let found = index.get(f, |v| fingerprints[v as usize] == f);
            if found.is_none() {
                index.insert(f, i as u32);
            }
            answers.push(found);
        }
        answers
    }

    fn as_hash_map_does(fingerprints: &[u64]) -> Vec<Option<u32>> {
        let mut map = HashMap::new();
        let answers = fingerprints.iter().enumerate().map(|(i, f)| {
            let found = map.get(f).copied();
            map.entry(*f).or_insert(i as u32);
            found
        });
        answers.collect()
    }

    #[test]
    fn fingerprints_sharing_their_tag_stay_apart_through_growth() {
        let fingerprints: Vec<u64> = (0..5000u64)
            .map(|i| (7 << 32) | (i % 2500))
            .chain((0..3000).map(|i| (u64::MAX - i) ^ (i << 40)))
            .collect();
        assert_eq!(index_all(&fingerprints), as_hash_map_does(&fingerprints));
    }

    proptest! {
        #[test]
        fn it_answers_as_a_hash_map_of_the_first_vertex_does(
            fingerprints in prop::collection::vec(
                prop_oneof![0u64..64, (0u64..8).prop_map(|t| t << 32 | 5), proptest::num::u64::ANY],
                0..3000,
            )
        ) {
            prop_assert_eq!(index_all(&fingerprints), as_hash_map_does(&fingerprints));
        }
    }
}
