//! The checks a structure edit gets before it lands: the app applies a
//! new body only if it passes, and the Model tab asks first, to say why
//! not while the user can still change it.

use biodyn::{Body, Preset, body};

/// The checks a preset file gets, on an edited model: the library's
/// `Body::validate`, then the preset's own rules (a segment may not be
/// called "seat", a share needs a body mass, …) by writing the model as
/// a preset and reading it back. The library's message on refusal.
pub fn check_model(preset: &Preset, body: &Body) -> Result<(), String> {
    body.validate().map_err(|e| e.to_string())?;
    let mut p = preset.clone();
    p.body = body.clone();
    let origin = body::Origin::Builtin(p.name.clone());
    match Preset::parse(&p.to_toml(), &origin) {
        Ok(_) => Ok(()),
        Err(body::PresetError::Field { message, .. }) => Err(message),
        Err(body::PresetError::Model { source, .. }) => Err(source.to_string()),
        Err(e) => Err(e.to_string()),
    }
}
