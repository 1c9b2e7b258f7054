//! Tests of the module above.

use super::*;

#[test]
fn table_and_ids_agree() {
    assert_eq!(ALL_P.len(), DEFS.len());
    for (i, p) in ALL_P.iter().enumerate() {
        assert_eq!(*p as usize, i);
    }
}

#[test]
fn names_resolve_in_manual_spellings() {
    for n in ["No.058", "no58", "058", "NO.058", "No058"] {
        assert_eq!(Settings::find(n).unwrap().0, P::No058, "{n}");
    }
    assert_eq!(Settings::find("NO182.7").unwrap().0, P::No182_7);
    assert_eq!(Settings::find("3401#0").unwrap().0, P::Fanuc3401_0);
    assert_eq!(Settings::find("5130").unwrap().0, P::Fanuc5130);
    assert!(Settings::find("No.999").is_none());
}

#[test]
fn assignment_checks_kind_range_and_dialect() {
    let mut s = Settings::new(Dialect::Gsk980tdc);
    s.assign("No.058=55").unwrap();
    assert_eq!(s.get(P::No058), 55.0);
    s.assign("x_mode=radius").unwrap();
    assert!(s.radius_x());
    assert!(matches!(s.assign("No.058=100"), Err(SettingError::OutOfRange(..))));
    assert!(matches!(s.assign("No.058=5.5"), Err(SettingError::BadValue(..))));
    assert!(matches!(s.assign("3401#0=1"), Err(SettingError::WrongDialect(..))));
    assert!(matches!(s.assign("nonsense=1"), Err(SettingError::Unknown(..))));
    assert!(matches!(s.assign("No.058"), Err(SettingError::Syntax(..))));
    assert!(matches!(s.assign("No.107=NaN"), Err(SettingError::BadValue(..))));
}

#[test]
fn text_settings_take_any_text_up_to_their_length() {
    let mut s = Settings::new(Dialect::Fanuc0i);
    assert_eq!(s.text(T::Designation), "");
    s.assign("thread.designation= M48x2-6g ").unwrap();
    assert_eq!(s.text(T::Designation), "M48x2-6g");
    s.assign("Thread.Designation=1/4-20 UNC-2A").unwrap();
    assert_eq!(s.text(T::Designation), "1/4-20 UNC-2A");
    let long = format!("thread.designation={}", "x".repeat(201));
    assert!(matches!(s.assign(&long), Err(SettingError::BadValue(..))));
    assert_eq!(s.text_entries().count(), 3);
    // An insert: its designation is read when it is set.
    s.assign("tool.insert=16ER 1.5 ISO").unwrap();
    assert!(matches!(s.assign("tool.insert=16ER 1.5 DIN"), Err(SettingError::BadValue(..))));
    // The common variables' start values: #n=value pairs, anything else refused.
    s.assign("macro.variables=#500=1.5 #501=-2").unwrap();
    assert_eq!(crate::exec::vars::parse_start(s.text(T::MacroVariables)), Ok(vec![(500, 1.5), (501, -2.0)]));
    assert!(matches!(s.assign("macro.variables=#500"), Err(SettingError::BadValue(..))));
    assert!(matches!(s.assign("macro.variables=#500=x"), Err(SettingError::BadValue(..))));
}

/// The decimals of the least input increment are those of the increment
/// itself, for IS-B and IS-C, metric and inch.
#[test]
fn length_digits_match_the_increment() {
    for is in [0.0, 1.0] {
        let mut s = Settings::new(Dialect::Fanuc0i);
        s.set(P::Increment, is);
        for inch in [false, true] {
            let inc = s.length_increment(inch);
            let d = s.length_digits(inch);
            assert!((inc - 10f64.powi(-i32::from(d))).abs() < 1e-15, "IS {is} inch {inch}: {inc} vs {d} digits");
        }
    }
}
