//! Neighbour lists in compressed sparse rows.

/// Neighbours of every particle in CSR form: the neighbours of `i` are
/// `indices[offsets[i]..offsets[i + 1]]`, ascending, never `i` itself.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct NeighborList {
    offsets: Vec<usize>,
    indices: Vec<u32>,
}

impl NeighborList {
    /// Builds from per-particle rows (each sorted ascending, self excluded).
    pub fn from_rows(rows: Vec<Vec<u32>>) -> Self {
        let mut offsets = Vec::with_capacity(rows.len() + 1);
        offsets.push(0);
        let total: usize = rows.iter().map(Vec::len).sum();
        let mut indices = Vec::with_capacity(total);
        for r in rows {
            indices.extend_from_slice(&r);
            offsets.push(indices.len());
        }
        Self { offsets, indices }
    }

    /// Builds from raw CSR arrays. `offsets` has one more entry than there are particles.
    pub(crate) fn from_raw(offsets: Vec<usize>, indices: Vec<u32>) -> Self {
        debug_assert_eq!(*offsets.last().unwrap_or(&0), indices.len());
        Self { offsets, indices }
    }

    /// Number of particles.
    pub fn len(&self) -> usize {
        self.offsets.len().saturating_sub(1)
    }
    /// True when the list covers no particles.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The neighbours of particle `i`, ascending.
    #[inline]
    pub fn neighbors(&self, i: usize) -> &[u32] {
        &self.indices[self.offsets[i]..self.offsets[i + 1]]
    }
    /// Number of neighbours of particle `i`.
    #[inline]
    pub fn count(&self, i: usize) -> usize {
        self.offsets[i + 1] - self.offsets[i]
    }
    /// Total number of (directed) pairs.
    pub fn total_pairs(&self) -> usize {
        self.indices.len()
    }
    /// Mean neighbour count (0 for no particles).
    pub fn mean_count(&self) -> f64 {
        if self.is_empty() {
            0.0
        } else {
            self.indices.len() as f64 / self.len() as f64
        }
    }
    /// Largest neighbour count.
    pub fn max_count(&self) -> usize {
        (0..self.len()).map(|i| self.count(i)).max().unwrap_or(0)
    }
    /// The CSR offsets (length `len() + 1`).
    pub fn offsets(&self) -> &[usize] {
        &self.offsets
    }
    /// The CSR column indices.
    pub fn indices(&self) -> &[u32] {
        &self.indices
    }
    /// Heap memory held, in bytes.
    pub fn memory_bytes(&self) -> usize {
        self.offsets.capacity() * std::mem::size_of::<usize>()
            + self.indices.capacity() * std::mem::size_of::<u32>()
    }
}
