//! A subset of a neighbour list's pairs, one bit per listed pair.
//!
//! Why bits: a list searched with a skin (a Verlet list) is kept over many stages, and
//! each stage needs the pairs that interact at its own positions, in the list's order.
//! Those are about five in six of the listed ones. Held as a second encoded list they
//! cost about as many bytes as the list itself (≈ 1.1 per pair); as bits, one eighth of
//! a byte per listed pair and the row's first bit (4 bytes per particle). Setting a bit
//! is cheaper than encoding the pair, too. The pair passes then decode each row of the
//! kept list into a buffer and keep the selected pairs without a branch per pair
//! ([`Pairs::row`]). A pass that reads every row anyway can make the selection as it
//! goes ([`RowPicker`], [`PairSelection::assemble`]): each row decoded once, the same
//! bits as [`NeighborList::select_pairs`].

use super::NeighborList;
use super::list::CHUNK;

/// Bits per group: the pairs of a row decoded at a time, one word of selection bits.
const GROUP: usize = 64;

/// The selection bits of `CHUNK` consecutive rows (the last chunk may hold fewer).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
struct ChunkBits {
    /// The bit of each row's first listed pair, one more than there are rows.
    starts: Vec<u32>,
    /// Bit b of the chunk is bit b % 64 of word b / 64: set where the pair is selected.
    words: Vec<u64>,
}

impl ChunkBits {
    /// `take` (≤ 64) bits from bit `bit` on, in the low bits of the result.
    #[inline]
    fn read(&self, bit: usize, take: usize) -> u64 {
        debug_assert!((1..=GROUP).contains(&take));
        let (w, o) = (bit / GROUP, bit % GROUP);
        let mut m = self.words[w] >> o;
        if o != 0 && o + take > GROUP {
            m |= self.words[w + 1] << (GROUP - o);
        }
        if take < GROUP {
            m & ((1u64 << take) - 1)
        } else {
            m
        }
    }

    /// The number of selected pairs among bits `start..end`.
    fn count(&self, start: usize, end: usize) -> usize {
        let mut n = 0;
        let mut b = start;
        while b < end {
            let take = (end - b).min(GROUP);
            n += self.read(b, take).count_ones() as usize;
            b += take;
        }
        n
    }
}

/// Which of a [`NeighborList`]'s pairs a test selected ([`NeighborList::select_pairs`]):
/// one bit per listed pair, read together with that list through [`Pairs`].
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PairSelection {
    chunks: Vec<ChunkBits>,
    len: usize,
}

impl PairSelection {
    /// Number of particles (rows) of the list it selects from.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when it covers no particles.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Heap memory held, in bytes.
    pub fn memory_bytes(&self) -> usize {
        self.chunks.capacity() * std::mem::size_of::<ChunkBits>()
            + self
                .chunks
                .iter()
                .map(|c| c.starts.capacity() * 4 + c.words.capacity() * 8)
                .sum::<usize>()
    }
}

/// The selection bits of one chunk as its rows are tested, in order.
struct ChunkBuilder {
    /// The finished words, and each tested row's first bit.
    bits: ChunkBits,
    /// The word being filled.
    word: u64,
    /// The chunk's bits so far.
    bit: usize,
}

impl ChunkBuilder {
    /// For a chunk of `rows` rows listing `pairs` pairs.
    fn new(rows: usize, pairs: usize) -> Self {
        let mut starts = Vec::with_capacity(rows + 1);
        starts.push(0);
        ChunkBuilder {
            bits: ChunkBits {
                starts,
                words: Vec::with_capacity(pairs.div_ceil(GROUP)),
            },
            word: 0,
            bit: 0,
        }
    }

    /// Rows of the chunk tested so far.
    fn rows(&self) -> usize {
        self.bits.starts.len() - 1
    }

    /// Tests the next row, particle `i` with the decoded neighbours `row`, storing the
    /// answers as bits. The tests run in runs that fill the current word: each run's bits
    /// gather in a register, with no store and no branch between two tests, so the loads
    /// of the partners' data can all be under way at once.
    #[inline]
    fn push_row<F: Fn(usize, u32) -> bool>(&mut self, i: usize, row: &[u32], keep: &F) {
        self.push_row_with(i, row, keep, |_, _| {});
    }

    /// [`Self::push_row`], calling `each(j, kept)` for each pair as it is tested.
    #[inline(always)]
    fn push_row_with<F, E>(&mut self, i: usize, row: &[u32], keep: &F, mut each: E)
    where
        F: Fn(usize, u32) -> bool,
        E: FnMut(u32, bool),
    {
        let mut rest = row;
        while !rest.is_empty() {
            let at = self.bit % GROUP;
            let (run, later) = rest.split_at((GROUP - at).min(rest.len()));
            let mut m = 0u64;
            for (b, &j) in run.iter().enumerate() {
                let kept = keep(i, j);
                each(j, kept);
                m |= u64::from(kept) << b;
            }
            self.word |= m << at;
            self.bit += run.len();
            if self.bit.is_multiple_of(GROUP) {
                self.bits.words.push(self.word);
                self.word = 0;
            }
            rest = later;
        }
        self.bits.starts.push(
            u32::try_from(self.bit).expect("a chunk of 256 rows lists fewer than 2^32 pairs"),
        );
    }

    fn finish(mut self) -> ChunkBits {
        if !self.bit.is_multiple_of(GROUP) {
            self.bits.words.push(self.word);
        }
        self.bits
    }
}

/// Tests the rows of chunk `c` that `b` has not tested, up to row `end` of the chunk
/// (not included), each decoded into `row`.
fn push_rows<F: Fn(usize, u32) -> bool>(
    c: &super::list::Chunk,
    b: &mut ChunkBuilder,
    (row, end): (&mut Vec<u32>, usize),
    keep: &F,
) {
    for k in b.rows()..end {
        let len = decode(c, k, row);
        b.push_row(c.first_row() + k, &row[..len], keep);
    }
}

/// Decodes row `k` of chunk `c` into `row` (grown as needed); returns its length.
#[inline]
fn decode(c: &super::list::Chunk, k: usize, row: &mut Vec<u32>) -> usize {
    let mut listed = c.row(k);
    let len = listed.len();
    if row.len() < len {
        row.resize(len, 0);
    }
    listed.fill(&mut row[..len]);
    len
}

impl NeighborList {
    /// The pairs of this list that `keep(i, j)` accepts: one pass over the rows, in
    /// parallel by chunks. `keep` is called for every listed pair and its answer stored
    /// as a bit, not branched on, so a test that fails in no pattern (a Verlet list's
    /// skin, sph-impact) costs no mispredicted branch. Read the selected pairs, each row
    /// in this list's order, with [`Pairs::selected`].
    pub fn select_pairs<F>(&self, keep: F) -> PairSelection
    where
        F: Fn(usize, u32) -> bool + Sync,
    {
        PairSelection::assemble(self, Vec::new(), keep)
    }

    /// A [`RowPicker`] over this list: the selection of [`Self::select_pairs`] made
    /// while a pass reads the rows, so that the pass decodes each row once and finds
    /// the partners' data it tests already in cache.
    pub fn picker(&self) -> RowPicker<'_> {
        RowPicker {
            list: self,
            open: None,
            done: Vec::new(),
            row: Vec::new(),
        }
    }
}

/// Picks a list's pairs row by row as a pass reads them ([`NeighborList::picker`]): each
/// [`Self::row`] tests a row's listed pairs with `keep`, as
/// [`NeighborList::select_pairs`] does, and hands back the accepted ones in order.
/// Several pickers may share a list's rows out (one per block of rows); their
/// [`PickedRows`] then make the whole selection ([`PairSelection::assemble`]), which
/// is [`NeighborList::select_pairs`]'s with the same test, bit for bit.
pub struct RowPicker<'a> {
    list: &'a NeighborList,
    /// The chunk being filled: its index and bits so far.
    open: Option<(usize, ChunkBuilder)>,
    done: Vec<(usize, ChunkBits)>,
    row: Vec<u32>,
}

/// The chunks of a list that a [`RowPicker`] tested, for [`PairSelection::assemble`].
pub struct PickedRows(Vec<(usize, ChunkBits)>);

impl RowPicker<'_> {
    /// The pairs of row `i` that `keep(i, j)` accepts, in the list's order, written into
    /// `out` (grown as needed). Rows come in ascending order; rows skipped within a
    /// chunk are tested too (their pairs are not handed back), so that each chunk the
    /// picker opens is whole when it closes.
    ///
    /// # Panics
    /// If `i` is not after the previous row asked for.
    pub fn row<'s, F>(&mut self, i: usize, keep: &F, out: &'s mut Vec<u32>) -> &'s [u32]
    where
        F: Fn(usize, u32) -> bool,
    {
        let c = i / CHUNK;
        if self.open.as_ref().is_some_and(|(open, _)| *open != c) {
            self.close(keep);
        }
        let chunk = &self.list.chunks()[c];
        let (open, b) = self
            .open
            .get_or_insert_with(|| (c, ChunkBuilder::new(chunk.rows(), chunk.pairs())));
        debug_assert_eq!(*open, c);
        let k = i % CHUNK;
        assert!(b.rows() <= k, "rows are picked in ascending order");
        push_rows(chunk, b, (&mut self.row, k), keep);
        let len = decode(chunk, k, &mut self.row);
        if out.len() < len {
            out.resize(len, 0);
        }
        // Each pair written at the next free place as it is tested, which moves on only
        // if it is accepted (no branch per pair).
        let mut n = 0;
        b.push_row_with(i, &self.row[..len], keep, |j, kept| {
            out[n] = j;
            n += usize::from(kept);
        });
        &out[..n]
    }

    /// Closes the open chunk, testing its rows not yet asked for.
    fn close<F: Fn(usize, u32) -> bool>(&mut self, keep: &F) {
        if let Some((c, mut b)) = self.open.take() {
            let chunk = &self.list.chunks()[c];
            push_rows(chunk, &mut b, (&mut self.row, chunk.rows()), keep);
            self.done.push((c, b.finish()));
        }
    }

    /// The chunks tested, the last one completed with `keep`.
    pub fn finish<F: Fn(usize, u32) -> bool>(mut self, keep: &F) -> PickedRows {
        self.close(keep);
        PickedRows(self.done)
    }
}

impl PairSelection {
    /// The selection of `list` made of the pickers' chunks (each from a [`RowPicker`] of
    /// `list` with the test `keep`), the chunks none of them opened picked here with
    /// `keep`: [`NeighborList::select_pairs`]`(keep)`, bit for bit.
    ///
    /// # Panics
    /// If two pickers opened the same chunk.
    pub fn assemble<F>(list: &NeighborList, picked: Vec<PickedRows>, keep: F) -> PairSelection
    where
        F: Fn(usize, u32) -> bool + Sync,
    {
        use rayon::prelude::*;
        let mut slots: Vec<Option<ChunkBits>> = vec![None; list.chunks().len()];
        for (c, bits) in picked.into_iter().flat_map(|p| p.0) {
            assert!(slots[c].is_none(), "a chunk is picked once");
            slots[c] = Some(bits);
        }
        let chunks = slots
            .into_par_iter()
            .zip(list.chunks().par_iter())
            .map(|(slot, c)| {
                slot.unwrap_or_else(|| {
                    let mut b = ChunkBuilder::new(c.rows(), c.pairs());
                    push_rows(c, &mut b, (&mut Vec::new(), c.rows()), &keep);
                    b.finish()
                })
            })
            .collect();
        PairSelection {
            chunks,
            len: list.len(),
        }
    }
}

/// The pairs a stage's passes read: every pair of a neighbour list, or those of it a
/// [`PairSelection`] selected, each row in the list's order.
#[derive(Clone, Copy, Debug)]
pub struct Pairs<'a> {
    list: &'a NeighborList,
    selection: Option<&'a PairSelection>,
}

impl<'a> Pairs<'a> {
    /// Every pair of `list`.
    pub fn all(list: &'a NeighborList) -> Self {
        Pairs {
            list,
            selection: None,
        }
    }

    /// The pairs of `list` that `selection` (made from it by
    /// [`NeighborList::select_pairs`]) selected.
    ///
    /// # Panics
    /// If `selection` covers another number of rows than `list`.
    pub fn selected(list: &'a NeighborList, selection: &'a PairSelection) -> Self {
        assert_eq!(
            list.len(),
            selection.len(),
            "a pair selection belongs to the list it was made from"
        );
        Pairs {
            list,
            selection: Some(selection),
        }
    }

    /// The list whose pairs these are (every listed pair, selected or not).
    pub fn list(&self) -> &'a NeighborList {
        self.list
    }

    /// Number of particles (rows).
    pub fn len(&self) -> usize {
        self.list.len()
    }

    /// True when there are no rows.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// The (selected) neighbours of particle `i`, ascending, decoded into `scratch`
    /// (grown as needed): the pair loops then read a plain slice. The row is decoded
    /// eight one-byte gaps at a time where it can be, and the pairs not selected are
    /// dropped without a branch per pair.
    pub fn row<'s>(&self, i: usize, scratch: &'s mut Vec<u32>) -> &'s [u32] {
        let mut listed = self.list.neighbors(i);
        let Some(s) = self.selection else {
            let len = listed.len();
            if scratch.len() < len {
                scratch.resize(len, 0);
            }
            listed.fill(&mut scratch[..len]);
            return &scratch[..len];
        };
        scratch.clear();
        let chunk = &s.chunks[i / CHUNK];
        let mut bit = chunk.starts[i % CHUNK] as usize;
        let mut kept = [0u32; GROUP];
        loop {
            let take = listed.len().min(GROUP);
            if take == 0 {
                break;
            }
            let n = listed.fill_selected(take, chunk.read(bit, take), &mut kept);
            bit += take;
            scratch.extend_from_slice(&kept[..n]);
        }
        scratch
    }

    /// Number of (selected) neighbours of particle `i`.
    pub fn count(&self, i: usize) -> usize {
        match self.selection {
            None => self.list.count(i),
            Some(s) => {
                let chunk = &s.chunks[i / CHUNK];
                let k = i % CHUNK;
                chunk.count(chunk.starts[k] as usize, chunk.starts[k + 1] as usize)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(n: usize, width: u32) -> Vec<Vec<u32>> {
        (0..n)
            .map(|i| {
                (0..n as u32)
                    .filter(|&j| j as usize != i && (j as usize + i) % 7 < width as usize)
                    .collect()
            })
            .collect()
    }

    /// The selected pairs are the accepted ones of each row, in order, across chunks and
    /// across groups of 64 (rows of up to 300 pairs), and an empty row stays a row.
    #[test]
    fn selected_pairs_are_the_accepted_ones_in_order() {
        let n = 2 * CHUNK + 3;
        for width in [0, 1, 3, 7] {
            let rows = rows(n, width);
            let list = NeighborList::from_rows(rows.clone());
            let keep = |i: usize, j: u32| !(i * 31 + j as usize * 17).is_multiple_of(5);
            let selection = list.select_pairs(keep);
            let pairs = Pairs::selected(&list, &selection);
            assert_eq!(pairs.len(), n);
            let mut scratch = Vec::new();
            for (i, row) in rows.iter().enumerate() {
                let want: Vec<u32> = row.iter().copied().filter(|&j| keep(i, j)).collect();
                assert_eq!(pairs.row(i, &mut scratch), want, "row {i}");
                assert_eq!(pairs.count(i), want.len(), "row {i}");
            }
        }
    }

    #[test]
    fn all_and_none_selected() {
        let list = NeighborList::from_rows(rows(CHUNK + 9, 5));
        let every = list.select_pairs(|_, _| true);
        let none = list.select_pairs(|_, _| false);
        let mut scratch = Vec::new();
        for i in 0..list.len() {
            let listed: Vec<u32> = list.neighbors(i).collect();
            assert_eq!(Pairs::all(&list).row(i, &mut scratch), listed);
            assert_eq!(Pairs::selected(&list, &every).row(i, &mut scratch), listed);
            assert!(
                Pairs::selected(&list, &none)
                    .row(i, &mut scratch)
                    .is_empty()
            );
            assert_eq!(Pairs::selected(&list, &none).count(i), 0);
            assert_eq!(Pairs::all(&list).count(i), listed.len());
        }
        // One bit per listed pair and one start per row.
        let bits = list.total_pairs().div_ceil(8);
        assert!(every.memory_bytes() >= bits + 4 * list.len());
        // At most: the bits, rounded up to a word per chunk, a start per row and one
        // more per chunk, and the chunks' headers.
        let chunks = list.len().div_ceil(CHUNK);
        let bound = bits
            + 8 * chunks
            + 4 * (list.len() + chunks)
            + every.chunks.capacity() * std::mem::size_of::<ChunkBits>();
        assert!(
            every.memory_bytes() <= bound,
            "{} bytes, {} pairs, bound {bound}",
            every.memory_bytes(),
            list.total_pairs()
        );
    }

    #[test]
    #[should_panic(expected = "belongs to the list")]
    fn a_selection_of_another_list_is_refused() {
        let a = NeighborList::from_rows(rows(10, 3));
        let b = NeighborList::from_rows(rows(11, 3));
        let s = a.select_pairs(|_, _| true);
        let _ = Pairs::selected(&b, &s);
    }

    proptest::proptest! {
        /// Any rows (up to 200 pairs each, so groups end anywhere in a word) and any
        /// selection read back as the accepted pairs.
        #[test]
        fn any_selection_reads_back(
            sets in proptest::collection::vec(
                proptest::collection::btree_set(0u32..5_000, 0..200),
                0..300,
            ),
            salt in 0usize..1_000,
        ) {
            let rows: Vec<Vec<u32>> = sets.into_iter().map(|s| s.into_iter().collect()).collect();
            let list = NeighborList::from_rows(rows.clone());
            let keep = |i: usize, j: u32| (i * 7 + j as usize * 13 + salt) % 11 < 8;
            let selection = list.select_pairs(keep);
            let pairs = Pairs::selected(&list, &selection);
            let mut scratch = Vec::new();
            for (i, r) in rows.iter().enumerate() {
                let want: Vec<u32> = r.iter().copied().filter(|&j| keep(i, j)).collect();
                proptest::prop_assert_eq!(pairs.row(i, &mut scratch), &want[..]);
                proptest::prop_assert_eq!(Pairs::all(&list).row(i, &mut scratch), &r[..]);
                proptest::prop_assert_eq!(pairs.count(i), want.len());
            }
        }

        /// Rows shared out among pickers in ascending runs (some rows skipped, some
        /// chunks left to `assemble`): each row handed back is its accepted pairs, and
        /// the assembled selection is `select_pairs`'s, bit for bit.
        #[test]
        fn pickers_assemble_the_selection(
            sets in proptest::collection::vec(
                proptest::collection::btree_set(0u32..5_000, 0..200),
                0..900,
            ),
            cuts in proptest::collection::btree_set(0usize..900, 0..6),
            skip in proptest::collection::btree_set(0usize..900, 0..40),
            salt in 0usize..1_000,
        ) {
            let rows: Vec<Vec<u32>> = sets.into_iter().map(|s| s.into_iter().collect()).collect();
            let n = rows.len();
            let list = NeighborList::from_rows(rows.clone());
            let keep = |i: usize, j: u32| (i * 7 + j as usize * 13 + salt) % 11 < 8;
            // Runs of rows between the cuts, each starting on a chunk's first row (as
            // the solver's blocks do); every other run is left to `assemble`.
            let mut starts: Vec<usize> = cuts.into_iter().map(|c| c / CHUNK * CHUNK).collect();
            starts.insert(0, 0);
            starts.push(n);
            starts.dedup();
            let mut picked = Vec::new();
            let mut out = Vec::new();
            for (k, w) in starts.windows(2).enumerate() {
                if k % 2 == 1 {
                    continue;
                }
                let mut picker = list.picker();
                for i in (w[0]..w[1].min(n)).filter(|i| !skip.contains(i)) {
                    let want: Vec<u32> = rows[i].iter().copied().filter(|&j| keep(i, j)).collect();
                    proptest::prop_assert_eq!(picker.row(i, &keep, &mut out), &want[..]);
                }
                picked.push(picker.finish(&keep));
            }
            let assembled = PairSelection::assemble(&list, picked, keep);
            proptest::prop_assert_eq!(&assembled, &list.select_pairs(keep));
        }
    }
}
