//! Renders through TestBackend and key sequences through the real `update`.
