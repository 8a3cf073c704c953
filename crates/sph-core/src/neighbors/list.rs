//! Neighbour lists in compressed sparse rows, stored in chunks of rows.

/// Rows per chunk (a power of two, so the chunk of a row is a shift away).
pub(crate) const CHUNK: usize = 256;
const CHUNK_SHIFT: u32 = CHUNK.trailing_zeros();

/// `CHUNK` consecutive rows of a list (the last chunk may hold fewer), in local CSR form.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct Chunk {
    /// Local offsets into `indices`, one more than there are rows.
    offsets: Vec<u32>,
    indices: Vec<u32>,
}

impl Chunk {
    /// An empty chunk that will receive `rows` rows through [`Self::push_row`].
    pub(crate) fn with_rows(rows: usize) -> Self {
        let mut offsets = Vec::with_capacity(rows + 1);
        offsets.push(0);
        Self {
            offsets,
            indices: Vec::new(),
        }
    }

    /// Appends the next row (sorted ascending, self excluded).
    pub(crate) fn push_row(&mut self, row: &[u32]) {
        self.indices.extend_from_slice(row);
        let end = u32::try_from(self.indices.len())
            .expect("a chunk of 256 rows holds fewer than 2^32 neighbour indices");
        self.offsets.push(end);
    }

    /// The chunk trimmed to its length (the indices grew by doubling).
    pub(crate) fn finish(mut self) -> Self {
        self.offsets.shrink_to_fit();
        self.indices.shrink_to_fit();
        self
    }

    fn rows(&self) -> usize {
        self.offsets.len() - 1
    }
}

/// Neighbours of every particle in compressed sparse rows (CSR): the neighbours of `i`,
/// ascending, never `i` itself.
///
/// The rows are kept in chunks of 256 particles, each with its own CSR arrays (local
/// `u32` offsets), exactly as the parallel search produces them: the list is never copied
/// into one array, so building it needs no second copy of the neighbour indices (the
/// largest array of a step), and it holds 4 bytes per index plus 4 per particle.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct NeighborList {
    chunks: Vec<Chunk>,
    len: usize,
}

impl NeighborList {
    /// Builds from per-particle rows (each sorted ascending, self excluded).
    pub fn from_rows(rows: Vec<Vec<u32>>) -> Self {
        let len = rows.len();
        let chunks = rows
            .chunks(CHUNK)
            .map(|block| {
                let mut chunk = Chunk::with_rows(block.len());
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
        let len = chunks.iter().map(Chunk::rows).sum();
        Self { chunks, len }
    }

    /// Number of particles.
    pub fn len(&self) -> usize {
        self.len
    }
    /// True when the list covers no particles.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The neighbours of particle `i`, ascending.
    #[inline]
    pub fn neighbors(&self, i: usize) -> &[u32] {
        let c = &self.chunks[i >> CHUNK_SHIFT];
        let k = i & (CHUNK - 1);
        &c.indices[c.offsets[k] as usize..c.offsets[k + 1] as usize]
    }
    /// Number of neighbours of particle `i`.
    #[inline]
    pub fn count(&self, i: usize) -> usize {
        let c = &self.chunks[i >> CHUNK_SHIFT];
        let k = i & (CHUNK - 1);
        (c.offsets[k + 1] - c.offsets[k]) as usize
    }
    /// Total number of (directed) pairs.
    pub fn total_pairs(&self) -> usize {
        self.chunks.iter().map(|c| c.indices.len()).sum()
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
                .map(|c| (c.offsets.capacity() + c.indices.capacity()) * 4)
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
            assert_eq!(list.neighbors(i), r.as_slice());
            assert_eq!(list.count(i), r.len());
        }
        assert_eq!(list.total_pairs(), rows.iter().map(Vec::len).sum::<usize>());
        assert_eq!(list.max_count(), 4);
        assert!(list.memory_bytes() >= 4 * (list.total_pairs() + n));
    }

    #[test]
    fn an_empty_list_has_no_rows() {
        let list = NeighborList::from_rows(Vec::new());
        assert!(list.is_empty());
        assert_eq!(list.mean_count(), 0.0);
        assert_eq!(list.max_count(), 0);
    }
}
