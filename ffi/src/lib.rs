//! The C ABI of ke-friction (work in progress).
