//! Which thread draws which tile. A model lands in a few tiles, so tiles' costs differ by two
//! orders of magnitude, and a thread left drawing a heavy tile at the end keeps the others
//! idle, as it did with the tile range halved between the threads (rayon's way). Handing the
//! tiles out one at a time, costliest first, to whichever thread is free fixed that but was
//! slower at 1920×1080: each frame moved tiles' memory to another core's cache. So each thread
//! owns a run of tiles of about equal cost, the same from frame to frame while the costs are,
//! and draws it in order (sorting a run by cost was slower too); a thread done with its run
//! takes tiles from the far end of the others'. Measured:
//! docs/performance.md#the-lightings-attenuation-and-sharing-the-tiles-between-the-threads

use std::marker::PhantomData;
use std::sync::atomic::{AtomicU64, Ordering};

use rayon::prelude::*;

use crate::target::{TILE_PIXELS, Target};
use crate::tile::TileBuffers;

/// Each thread's run of tiles, kept from frame to frame so that a steady frame allocates
/// nothing.
#[derive(Debug, Default)]
pub(crate) struct TileRuns {
    /// The tiles of each run not yet taken (see [`Share`]).
    shares: Vec<AtomicU64>,
}

impl TileRuns {
    /// Draws every tile of `target` with `draw(tile, buffers)`, on every thread of the pool.
    /// A tile's `cost` need only be proportional to its drawing time.
    pub(crate) fn draw(
        &mut self,
        target: &mut Target,
        cost: impl Fn(usize) -> usize,
        draw: impl Fn(usize, TileBuffers<'_>) + Sync,
    ) {
        let threads = rayon::current_num_threads();
        self.plan(target.grid.tiles(), threads, cost);
        let handout = Handout::new(target, &self.shares);
        // Task k owns run k. Rayon runs the first task on the calling thread, as it runs the
        // first half of every parallel loop, such as the copy-out's (`Target::resolve`).
        (0..threads)
            .into_par_iter()
            .with_max_len(1)
            .for_each(|own| {
                let others = (1..threads).map(|i| (own + i) % threads);
                let take = |share, end| {
                    while let Some((tile, buffers)) = handout.take(share, end) {
                        draw(tile, buffers);
                    }
                };
                take(own, End::Front);
                others.for_each(|share| take(share, End::Back));
            });
    }

    /// Cuts the tiles into `threads` runs of about equal cost (an empty tile still costs its
    /// clearing).
    fn plan(&mut self, tiles: usize, threads: usize, cost: impl Fn(usize) -> usize) {
        // A run's ends are packed as two u32 (far beyond any viewport's tiles).
        assert!(u32::try_from(tiles).is_ok(), "{tiles} tiles");
        let total: usize = (0..tiles).map(|tile| cost(tile) + 1).sum();
        self.shares.resize_with(threads, || AtomicU64::new(0));
        let (mut start, mut sum) = (0, 0);
        for (share, run) in self.shares.iter_mut().enumerate() {
            let goal = total * (share + 1) / threads;
            let mut end = start;
            while end < tiles && (sum < goal || share + 1 == threads) {
                sum += cost(end) + 1;
                end += 1;
            }
            *run.get_mut() = Share {
                front: start,
                back: end,
            }
            .pack();
            start = end;
        }
    }
}

/// The tiles of a run not yet taken: its thread takes from the front, the others from the
/// back, both through one atomic word so that the two ends never pass each other.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Share {
    front: usize,
    back: usize,
}

impl Share {
    fn pack(self) -> u64 {
        (self.front as u64) << 32 | self.back as u64
    }

    fn unpack(word: u64) -> Share {
        Share {
            front: (word >> 32) as usize,
            back: (word & u64::from(u32::MAX)) as usize,
        }
    }
}

/// Which end of a run to take from.
#[derive(Clone, Copy, Debug)]
enum End {
    Front,
    Back,
}

/// Hands out each tile's piece of the target's buffers once, to one thread.
struct Handout<'a> {
    shares: &'a [AtomicU64],
    color: *mut u32,
    depth: *mut f32,
    visible: *mut u32,
    /// Null when the id buffer is not recorded (and empty).
    ids: *mut u32,
    target: PhantomData<&'a mut Target>,
}

// SAFETY: the pointers become slices only in `take`, which gives each tile's to one caller.
unsafe impl Sync for Handout<'_> {}

impl<'a> Handout<'a> {
    /// `shares` are runs of `target`'s tiles that do not overlap (`TileRuns::plan` makes them
    /// so).
    fn new(target: &'a mut Target, shares: &'a [AtomicU64]) -> Handout<'a> {
        let pixels = target.grid.tiles() * TILE_PIXELS;
        let buffers = [target.color.len(), target.depth.len(), target.visible.len()];
        assert!(
            buffers.iter().all(|&len| len == pixels),
            "tile buffers sized for the grid"
        );
        assert!(target.ids.is_empty() || target.ids.len() == pixels);
        Handout {
            shares,
            color: target.color.as_mut_ptr(),
            depth: target.depth.as_mut_ptr(),
            visible: target.visible.as_mut_ptr(),
            ids: match target.ids.is_empty() {
                true => std::ptr::null_mut(),
                false => target.ids.as_mut_ptr(),
            },
            target: PhantomData,
        }
    }

    /// The tile at one `end` of `share` and its buffers, or None when the run is all taken.
    fn take(&self, share: usize, end: End) -> Option<(usize, TileBuffers<'a>)> {
        let word = &self.shares[share];
        let mut current = word.load(Ordering::Relaxed);
        let tile = loop {
            let Share { front, back } = Share::unpack(current);
            if front >= back {
                return None;
            }
            let (tile, rest) = match end {
                End::Front => (
                    front,
                    Share {
                        front: front + 1,
                        back,
                    },
                ),
                End::Back => (
                    back - 1,
                    Share {
                        front,
                        back: back - 1,
                    },
                ),
            };
            match word.compare_exchange_weak(
                current,
                rest.pack(),
                Ordering::Relaxed,
                Ordering::Relaxed,
            ) {
                Ok(_) => break tile,
                Err(now) => current = now,
            }
        };
        let at = tile * TILE_PIXELS;
        // SAFETY: a run's two ends move towards each other in one atomic word and the runs do
        // not overlap, so no tile's pieces are handed out twice; `new` checked that every tile lies within the buffers (the id
        // buffer when it is recorded), which stay mutably borrowed for 'a.
        let buffers = unsafe {
            TileBuffers {
                color: piece(self.color, at),
                depth: piece(self.depth, at),
                visible: piece(self.visible, at),
                ids: match self.ids.is_null() {
                    true => &mut [],
                    false => piece(self.ids, at),
                },
            }
        };
        Some((tile, buffers))
    }
}

/// The tile's pixels from `at` in the buffer at `start`.
///
/// # Safety
/// The buffer holds `at + TILE_PIXELS` elements, and nothing else refers to those for 'b.
unsafe fn piece<'b, T>(start: *mut T, at: usize) -> &'b mut [T] {
    // SAFETY: as the caller promises.
    unsafe { std::slice::from_raw_parts_mut(start.add(at), TILE_PIXELS) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_tile_is_drawn_once_into_its_own_pixels() {
        let mut target = Target::default();
        target.resize(64 * 5, 64 * 3, true);
        let tiles = target.grid.tiles();
        let drawn = std::sync::Mutex::new(Vec::new());
        let mut runs = TileRuns::default();
        runs.draw(
            &mut target,
            |tile| (tile * 7) % 5,
            |tile, buffers| {
                drawn.lock().unwrap().push(tile);
                buffers.color.fill(tile as u32);
                buffers.ids.fill(tile as u32);
            },
        );
        let mut drawn = drawn.into_inner().unwrap();
        drawn.sort();
        assert_eq!(drawn, (0..tiles).collect::<Vec<_>>());
        for (tile, pixels) in target.color.chunks(TILE_PIXELS).enumerate() {
            assert!(pixels.iter().all(|&p| p == tile as u32));
        }
        assert_eq!(target.color, target.ids);
    }

    #[test]
    fn shares_are_runs_of_about_equal_cost() {
        // Costs (plus 1 for clearing) 1, 1, 9, 1, 5, 1, 1, 2: a total of 21, 10.5 per share.
        let costs = [0, 0, 8, 0, 4, 0, 0, 1];
        let mut runs = TileRuns::default();
        runs.plan(costs.len(), 2, |tile| costs[tile]);
        let shares: Vec<Share> = runs
            .shares
            .iter()
            .map(|s| Share::unpack(s.load(Ordering::Relaxed)))
            .collect();
        assert_eq!(
            shares,
            [Share { front: 0, back: 3 }, Share { front: 3, back: 8 }]
        );
        // Three threads on one costly tile: the shares after it are empty, not missing.
        runs.plan(2, 3, |tile| [100, 0][tile]);
        let shares: Vec<Share> = runs
            .shares
            .iter()
            .map(|s| Share::unpack(s.load(Ordering::Relaxed)))
            .collect();
        let ends = [(0, 1), (1, 1), (1, 2)].map(|(front, back)| Share { front, back });
        assert_eq!(shares, ends);
    }

    #[test]
    fn a_run_taken_from_both_ends_gives_each_tile_once() {
        let mut target = Target::default();
        target.resize(64 * 4, 64, false);
        let mut runs = TileRuns::default();
        runs.plan(4, 1, |_| 0);
        let handout = Handout::new(&mut target, &runs.shares);
        let mut taken = Vec::new();
        for end in [
            End::Front,
            End::Back,
            End::Back,
            End::Front,
            End::Front,
            End::Back,
        ] {
            taken.extend(handout.take(0, end).map(|(tile, _)| tile));
        }
        assert_eq!(taken, [0, 3, 2, 1]);
    }
}
