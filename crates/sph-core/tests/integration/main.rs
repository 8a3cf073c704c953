//! sph-core integration tests: tensor algebra against nalgebra, neighbour search against
//! brute force.

mod halo;
mod neighbors;
mod tensors;
