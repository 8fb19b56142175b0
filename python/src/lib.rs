//! Python bindings of ke-friction (work in progress).
