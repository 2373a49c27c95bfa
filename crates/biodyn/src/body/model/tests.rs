//! The body model: structure, validation, parameters.

use super::*;

#[test]
fn paper_model_is_valid_chain() {
    let b = Body::paper(75.0).unwrap();
    assert_eq!(b.n(), 4);
    assert!(b.is_tridiagonal());
    assert!((b.seated_mass() - 0.781 * 75.0).abs() < 1e-12);
    assert_eq!(b.links[3].lower, End::Seat);
    assert_eq!(b.links[3].name, "pelvis-seat");
}

#[test]
fn validation_names_the_field() {
    let mut b = Body::paper(75.0).unwrap();
    b.segments[2].mass = -1.0;
    let e = b.validate().unwrap_err().to_string();
    assert!(e.contains("lower-torso") && e.contains("-1"), "{e}");

    let mut b = Body::paper(75.0).unwrap();
    b.links[0].k = 1e50;
    assert!(matches!(b.validate(), Err(ModelError::BadLinkValue { .. })));

    let mut b = Body::paper(75.0).unwrap();
    b.links[1].c = f64::NAN;
    assert!(matches!(b.validate(), Err(ModelError::BadLinkValue { .. })));

    let mut b = Body::paper(75.0).unwrap();
    b.links[3].lower = End::Segment(0);
    assert_eq!(b.validate(), Err(ModelError::NoSeatLink));

    let mut b = Body::paper(75.0).unwrap();
    b.segments[1].name = "head-neck".into();
    assert!(matches!(b.validate(), Err(ModelError::DuplicateSegment(_))));
}

#[test]
fn floating_segment_is_rejected() {
    let mut b = Body::paper(75.0).unwrap();
    // Cut the chest from the lower torso: head and chest float.
    b.links.remove(1);
    assert_eq!(
        b.validate(),
        Err(ModelError::Floating("head-neck".to_string()))
    );
}

#[test]
fn a_link_with_nothing_in_it_ties_nothing() {
    let mut b = Body::paper(75.0).unwrap();
    b.links[0].k = 0.0;
    b.links[0].c = 0.0;
    assert_eq!(b.validate(), Err(ModelError::Floating("head-neck".into())));
    b.links[0].c = 1.0;
    assert!(b.validate().is_ok());
}

#[test]
fn params_resolve_by_number_and_name() {
    let b = Body::paper(75.0).unwrap();
    assert_eq!(b.param("k4").unwrap(), Param::Stiffness(3));
    assert_eq!(b.param("m1").unwrap(), Param::Mass(0));
    assert_eq!(b.param("chest").unwrap(), Param::Mass(1));
    assert_eq!(b.param("pelvis-seat.c").unwrap(), Param::Damping(3));
    assert_eq!(b.param("body_mass").unwrap(), Param::BodyMass);
    assert!(b.param("k5").is_err());
    assert!(b.param("k0").is_err());
    assert!(b.param("x1").is_err());
    assert!(b.param("pelvis-seat.z").is_err());
}

#[test]
fn set_rejects_bad_values_and_keeps_body() {
    let mut b = Body::paper(75.0).unwrap();
    let before = b.clone();
    assert!(b.set(Param::Mass(0), 0.0).is_err());
    assert!(b.set(Param::Stiffness(3), -5.0).is_err());
    assert!(b.set(Param::BodyMass, f64::INFINITY).is_err());
    assert_eq!(b, before);
    b.set(Param::BodyMass, 85.0).unwrap();
    assert!((b.segments[1].mass - 0.402 * 85.0).abs() < 1e-12);
    // A mass set by hand moves its share, so rescaling keeps it in proportion.
    b.set(Param::Mass(3), 20.0).unwrap();
    b.set(Param::BodyMass, 42.5).unwrap();
    assert!((b.segments[3].mass - 10.0).abs() < 1e-12);
}

#[test]
fn a_non_ascii_parameter_name_is_unknown_not_a_panic() {
    let b = Body::paper(75.0).unwrap();
    for name in ["é", "é1", "€2", "ß", "\u{0}", ""] {
        assert!(
            matches!(b.param(name), Err(ModelError::UnknownParam(_))),
            "{name:?}"
        );
    }
}
