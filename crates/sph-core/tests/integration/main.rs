//! sph-core integration tests: tensor algebra against nalgebra, neighbour search against
//! brute force.

mod neighbors;
mod tensors;
