//! Neighbour lists in compressed sparse rows, stored in chunks of rows, each row
//! delta-encoded in bytes.
//!
//! Why encoded: the list is the largest array of a step (≈ 65 neighbours per particle in
//! 3-D, 260 bytes as `u32`), and a row's indices, sorted, are close to each other and to
//! the particle's own index for any spatially coherent ordering (lattices, Morton order).
//! A row is stored as LEB128 varints: its length, the zigzag-coded offset of its first
//! neighbour from the particle's index, then each gap to the next neighbour minus one. A
//! gap below 128 takes one byte, below 16 384 two. Decoding is a few integer operations
//! per neighbour, small beside the pair terms that follow.

/// Rows per chunk (a power of two, so the chunk of a row is a shift away).
pub(crate) const CHUNK: usize = 256;
const CHUNK_SHIFT: u32 = CHUNK.trailing_zeros();

/// Appends `v` as an LEB128 varint (7 bits per byte, high bit = more follows).
#[inline]
fn put_varint(out: &mut Vec<u8>, mut v: u64) {
    while v >= 0x80 {
        out.push((v as u8) | 0x80);
        v >>= 7;
    }
    out.push(v as u8);
}

/// Reads an LEB128 varint at `*pos` and advances past it.
#[inline(always)]
fn get_varint(bytes: &[u8], pos: &mut usize) -> u64 {
    let mut v = 0u64;
    let mut shift = 0;
    loop {
        let b = bytes[*pos];
        *pos += 1;
        v |= u64::from(b & 0x7f) << shift;
        if b < 0x80 {
            return v;
        }
        shift += 7;
    }
}

/// The first entry's offset from the row's own index (zigzag-coded, see the module docs).
#[inline(always)]
fn unzigzag(code: u64) -> i64 {
    (code >> 1) as i64 ^ -((code & 1) as i64)
}

/// The eight bytes at `pos` as a little-endian word, where all eight are one-byte codes
/// (gaps below 128, the common case): the group decoders read them without a branch per
/// byte.
#[inline(always)]
fn eight_one_byte_codes(bytes: &[u8], pos: usize) -> Option<u64> {
    let word = bytes.get(pos..pos + 8)?;
    let w = u64::from_le_bytes(word.try_into().expect("eight bytes"));
    (w & 0x8080_8080_8080_8080 == 0).then_some(w)
}

/// `CHUNK` consecutive rows of a list (the last chunk may hold fewer): the encoded rows
/// one after another, and where each starts.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Chunk {
    /// Index of the chunk's first row.
    first_row: usize,
    /// Byte offsets of the rows in `bytes`, one more than there are rows.
    offsets: Vec<u32>,
    bytes: Vec<u8>,
    /// Neighbour indices held (the sum of the rows' lengths).
    pairs: usize,
}

impl Chunk {
    /// An empty chunk whose first row is `first_row`, that will receive `rows` rows
    /// through [`Self::push_row`].
    pub(crate) fn with_rows(first_row: usize, rows: usize) -> Self {
        let mut offsets = Vec::with_capacity(rows + 1);
        offsets.push(0);
        Self {
            first_row,
            offsets,
            bytes: Vec::new(),
            pairs: 0,
        }
    }

    /// Appends the next row (strictly ascending, self excluded).
    pub(crate) fn push_row(&mut self, row: &[u32]) {
        let i = (self.first_row + self.rows()) as i64;
        put_varint(&mut self.bytes, row.len() as u64);
        if let Some((&first, rest)) = row.split_first() {
            let d = i64::from(first) - i;
            // Zigzag: small offsets of either sign become small codes.
            put_varint(&mut self.bytes, ((d << 1) ^ (d >> 63)) as u64);
            let mut prev = first;
            for &j in rest {
                debug_assert!(j > prev, "neighbour rows must be strictly ascending");
                put_varint(&mut self.bytes, u64::from(j - prev - 1));
                prev = j;
            }
        }
        self.pairs += row.len();
        let end = u32::try_from(self.bytes.len())
            .expect("a chunk of 256 rows holds fewer than 2^32 bytes of neighbour indices");
        self.offsets.push(end);
    }

    /// Appends row `k` of `other` (a chunk of the same rows) as it is encoded there: a
    /// row's bytes depend only on its entries and its own index.
    pub(crate) fn push_row_of(&mut self, other: &Chunk, k: usize) {
        debug_assert_eq!(self.first_row + self.rows(), other.first_row + k);
        let (a, b) = (other.offsets[k] as usize, other.offsets[k + 1] as usize);
        self.bytes.extend_from_slice(&other.bytes[a..b]);
        self.pairs += other.row(k).len();
        let end = u32::try_from(self.bytes.len())
            .expect("a chunk of 256 rows holds fewer than 2^32 bytes of neighbour indices");
        self.offsets.push(end);
    }

    /// The chunk trimmed to its length (the bytes grew by doubling).
    pub(crate) fn finish(mut self) -> Self {
        self.offsets.shrink_to_fit();
        self.bytes.shrink_to_fit();
        self
    }

    /// Index of the chunk's first row.
    pub(crate) fn first_row(&self) -> usize {
        self.first_row
    }

    /// Neighbour indices held (the sum of the rows' lengths).
    pub(crate) fn pairs(&self) -> usize {
        self.pairs
    }

    /// Rows held.
    pub(crate) fn rows(&self) -> usize {
        self.offsets.len() - 1
    }

    /// Row `k` of the chunk.
    #[inline]
    pub(crate) fn row(&self, k: usize) -> Neighbors<'_> {
        let mut pos = self.offsets[k] as usize;
        let len = get_varint(&self.bytes, &mut pos) as usize;
        Neighbors {
            bytes: &self.bytes,
            pos,
            prev: (self.first_row + k) as i64,
            left: len,
            first: true,
        }
    }
}

/// The neighbours of one particle, ascending, decoded as they are read.
#[derive(Clone, Debug)]
pub struct Neighbors<'a> {
    bytes: &'a [u8],
    pos: usize,
    /// The last index read (before the first: the particle's own index).
    prev: i64,
    left: usize,
    first: bool,
}

impl Neighbors<'_> {
    /// Decodes the next `out.len()` neighbours into `out`, which must be at most as many
    /// as are left: the row's state held in registers for the whole group, where a
    /// caller that stores each index next to the iterator would have it reloaded.
    #[inline]
    pub(crate) fn fill(&mut self, out: &mut [u32]) {
        debug_assert!(out.len() <= self.left);
        let (bytes, mut pos, mut prev) = (self.bytes, self.pos, self.prev);
        let mut from = 0;
        if self.first
            && let Some(slot) = out.first_mut()
        {
            prev += unzigzag(get_varint(bytes, &mut pos));
            *slot = prev as u32;
            from = 1;
            self.first = false;
        }
        let mut rest = &mut out[from..];
        while !rest.is_empty() {
            // Eight one-byte gaps at once where the next eight bytes are all one-byte
            // codes (most gaps are below 128): no branch per byte.
            if rest.len() >= 8
                && let Some(w) = eight_one_byte_codes(bytes, pos)
            {
                let (group, tail) = rest.split_at_mut(8);
                for (k, slot) in group.iter_mut().enumerate() {
                    prev += ((w >> (8 * k)) & 0x7f) as i64 + 1;
                    *slot = prev as u32;
                }
                pos += 8;
                rest = tail;
                continue;
            }
            let (slot, tail) = rest.split_first_mut().expect("not empty");
            prev += get_varint(bytes, &mut pos) as i64 + 1;
            *slot = prev as u32;
            rest = tail;
        }
        self.pos = pos;
        self.prev = prev;
        self.left -= out.len();
    }

    /// Decodes the next `take` neighbours (at most 64, and at most as many as are left)
    /// and keeps those whose bit of `selected` is set (bit k for the k-th), at the start
    /// of `out` in order; returns how many were kept. Each is written at the next free
    /// place, which moves on only if it is kept, so there is no branch per neighbour;
    /// eight one-byte gaps are decoded at once as in [`Self::fill`].
    #[inline]
    pub(crate) fn fill_selected(
        &mut self,
        take: usize,
        selected: u64,
        out: &mut [u32; 64],
    ) -> usize {
        debug_assert!(take <= 64 && take <= self.left);
        let (bytes, mut pos, mut prev) = (self.bytes, self.pos, self.prev);
        let (mut k, mut n) = (0, 0);
        if self.first && take > 0 {
            prev += unzigzag(get_varint(bytes, &mut pos));
            out[0] = prev as u32;
            n = (selected & 1) as usize;
            k = 1;
            self.first = false;
        }
        while k < take {
            if take - k >= 8
                && let Some(w) = eight_one_byte_codes(bytes, pos)
            {
                let bits = selected >> k;
                for b in 0..8 {
                    prev += ((w >> (8 * b)) & 0x7f) as i64 + 1;
                    // n ≤ k + b < 64 here: the mask only spares a bounds test.
                    out[n % 64] = prev as u32;
                    n += ((bits >> b) & 1) as usize;
                }
                pos += 8;
                k += 8;
                continue;
            }
            prev += get_varint(bytes, &mut pos) as i64 + 1;
            out[n % 64] = prev as u32;
            n += ((selected >> k) & 1) as usize;
            k += 1;
        }
        self.pos = pos;
        self.prev = prev;
        self.left -= take;
        n
    }
}

impl Iterator for Neighbors<'_> {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let code = get_varint(self.bytes, &mut self.pos);
        self.prev = if self.first {
            self.first = false;
            self.prev + unzigzag(code)
        } else {
            self.prev + code as i64 + 1
        };
        Some(self.prev as u32)
    }

    #[inline]
    fn size_hint(&self) -> (usize, Option<usize>) {
        (self.left, Some(self.left))
    }
}

impl ExactSizeIterator for Neighbors<'_> {}
impl std::iter::FusedIterator for Neighbors<'_> {}

/// Neighbours of every particle in compressed sparse rows (CSR): the neighbours of `i`,
/// ascending, never `i` itself.
///
/// The rows are kept in chunks of 256 particles, exactly as the parallel search produces
/// them (the list is never copied into one array), each row delta-encoded in bytes (see
/// the module docs): about 1.1 bytes per neighbour on a 3-D lattice instead of 4, plus 4
/// per particle for the row offsets. [`Self::neighbors`] decodes a row as it is iterated.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct NeighborList {
    chunks: Vec<Chunk>,
    len: usize,
}

impl NeighborList {
    /// Builds from per-particle rows (each strictly ascending, self excluded).
    pub fn from_rows(rows: Vec<Vec<u32>>) -> Self {
        let len = rows.len();
        let chunks = rows
            .chunks(CHUNK)
            .enumerate()
            .map(|(c, block)| {
                let mut chunk = Chunk::with_rows(c * CHUNK, block.len());
                for r in block {
                    chunk.push_row(r);
                }
                chunk.finish()
            })
            .collect();
        Self { chunks, len }
    }

    /// Builds from chunks of `CHUNK` rows each (the last may be shorter).
    pub(crate) fn from_chunks(chunks: Vec<Chunk>) -> Self {
        debug_assert!(chunks.iter().rev().skip(1).all(|c| c.rows() == CHUNK));
        debug_assert!(
            chunks
                .iter()
                .enumerate()
                .all(|(c, k)| k.first_row == c * CHUNK)
        );
        let len = chunks.iter().map(Chunk::rows).sum();
        Self { chunks, len }
    }

    /// The chunks of rows.
    pub(crate) fn chunks(&self) -> &[Chunk] {
        &self.chunks
    }

    /// Number of particles.
    pub fn len(&self) -> usize {
        self.len
    }
    /// True when the list covers no particles.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The neighbours of particle `i`, ascending (decoded as they are iterated; collect
    /// them when random access is needed).
    #[inline]
    pub fn neighbors(&self, i: usize) -> Neighbors<'_> {
        self.chunks[i >> CHUNK_SHIFT].row(i & (CHUNK - 1))
    }
    /// Number of neighbours of particle `i`.
    #[inline]
    pub fn count(&self, i: usize) -> usize {
        self.neighbors(i).len()
    }
    /// Total number of (directed) pairs.
    pub fn total_pairs(&self) -> usize {
        self.chunks.iter().map(|c| c.pairs).sum()
    }
    /// Mean neighbour count (0 for no particles).
    pub fn mean_count(&self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            self.total_pairs() as f64 / self.len() as f64
        }
    }
    /// Largest neighbour count.
    pub fn max_count(&self) -> usize {
        (0..self.len()).map(|i| self.count(i)).max().unwrap_or(0)
    }
    /// Heap memory held, in bytes.
    pub fn memory_bytes(&self) -> usize {
        self.chunks.capacity() * std::mem::size_of::<Chunk>()
            + self
                .chunks
                .iter()
                .map(|c| c.offsets.capacity() * 4 + c.bytes.capacity())
                .sum::<usize>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_across_chunk_boundaries_read_back() {
        let n = 2 * CHUNK + 7;
        let rows: Vec<Vec<u32>> = (0..n)
            .map(|i| (0..(i % 5) as u32).map(|k| k * 3 + 1).collect())
            .collect();
        let list = NeighborList::from_rows(rows.clone());
        assert_eq!(list.len(), n);
        for (i, r) in rows.iter().enumerate() {
            assert_eq!(list.neighbors(i).collect::<Vec<_>>(), *r);
            assert_eq!(list.count(i), r.len());
        }
        assert_eq!(list.total_pairs(), rows.iter().map(Vec::len).sum::<usize>());
        assert_eq!(list.max_count(), 4);
        assert!(list.memory_bytes() >= list.total_pairs() + 4 * n);
    }

    #[test]
    fn far_and_backward_neighbours_round_trip() {
        // First neighbours far below and above the row's own index, gaps of every
        // varint length (1 to 5 bytes), empty rows between.
        let rows: Vec<Vec<u32>> = vec![
            vec![u32::MAX - 1, u32::MAX],
            vec![],
            vec![0, 1, 128, 16_512, 2_113_664, 270_549_120, u32::MAX],
            vec![1],
            vec![0, 2, 4],
        ];
        let list = NeighborList::from_rows(rows.clone());
        for (i, r) in rows.iter().enumerate() {
            assert_eq!(list.neighbors(i).collect::<Vec<_>>(), *r, "row {i}");
            assert_eq!(list.neighbors(i).len(), r.len());
        }
        assert_eq!(list.total_pairs(), 13);
    }

    proptest::proptest! {
        #[test]
        fn any_sorted_rows_round_trip(
            sets in proptest::collection::vec(
                proptest::collection::btree_set(proptest::prelude::any::<u32>(), 0..40),
                0..600,
            )
        ) {
            let rows: Vec<Vec<u32>> = sets.into_iter().map(|s| s.into_iter().collect()).collect();
            let list = NeighborList::from_rows(rows.clone());
            proptest::prop_assert_eq!(list.len(), rows.len());
            for (i, r) in rows.iter().enumerate() {
                proptest::prop_assert_eq!(&list.neighbors(i).collect::<Vec<_>>(), r);
                proptest::prop_assert_eq!(list.count(i), r.len());
            }
        }

        /// Decoding in groups (`Neighbors::fill`), then by `next`, reads the same row.
        #[test]
        fn groups_decode_the_row(
            set in proptest::collection::btree_set(proptest::prelude::any::<u32>(), 0..100),
            i in 0usize..300,
            group in 1usize..20,
        ) {
            let row: Vec<u32> = set.into_iter().filter(|&j| j as usize != i).collect();
            let mut rows = vec![Vec::new(); i];
            rows.push(row.clone());
            let list = NeighborList::from_rows(rows);
            let mut it = list.neighbors(i);
            let mut read = Vec::new();
            while it.len() >= group {
                let mut buf = vec![0; group];
                it.fill(&mut buf);
                read.extend(buf);
            }
            read.extend(it);
            proptest::prop_assert_eq!(read, row);
        }

        /// Decoding in groups of up to 64 keeping the selected ones
        /// (`Neighbors::fill_selected`) reads the selected neighbours of the row.
        #[test]
        fn selected_groups_decode_the_selected(
            set in proptest::collection::btree_set(0u32..3_000, 0..200),
            i in 0usize..300,
            group in 1usize..=64,
            seed in proptest::prelude::any::<u64>(),
        ) {
            let row: Vec<u32> = set.into_iter().filter(|&j| j as usize != i).collect();
            let mut rows = vec![Vec::new(); i];
            rows.push(row.clone());
            let list = NeighborList::from_rows(rows);
            let keep = |k: usize| (seed.rotate_left(k as u32 % 64) ^ k as u64) & 1 == 1;
            let mut it = list.neighbors(i);
            let (mut read, mut out, mut k0) = (Vec::new(), [0u32; 64], 0);
            loop {
                let take = it.len().min(group);
                if take == 0 {
                    break;
                }
                let m = (0..take).fold(0u64, |m, k| m | (u64::from(keep(k0 + k)) << k));
                let n = it.fill_selected(take, m, &mut out);
                read.extend_from_slice(&out[..n]);
                k0 += take;
            }
            let want: Vec<u32> =
                row.iter().enumerate().filter(|&(k, _)| keep(k)).map(|(_, &j)| j).collect();
            proptest::prop_assert_eq!(read, want);
        }
    }

    #[test]
    fn an_empty_list_has_no_rows() {
        let list = NeighborList::from_rows(Vec::new());
        assert!(list.is_empty());
        assert_eq!(list.mean_count(), 0.0);
        assert_eq!(list.max_count(), 0);
    }
}
