//! What a reader sees is true: the book and its lessons, the README and the
//! pages it points to, guided step-throughs, and the shape of the house.

mod architecture;
mod book;
mod browser;
mod guide;
mod paths;
mod readme;
mod structures;
mod vectors;
