//! Another program's passes laid over a drawing (the app's "Compare
//! with…"): the cuts, run-outs and screw-ins of the side section and the
//! tool at each pass of the tooth section, in one pen of their own, without
//! source lines (hovering them marks nothing of the program in the editor).

use super::scene::{Item, Scene, Shape, Style};

/// The items of `other` (the same view of the other program) to lay over a drawing.
pub fn items(other: &Scene) -> Vec<Item> {
    other
        .items
        .iter()
        .filter(|i| i.pass.is_some() && matches!(i.shape, Shape::Polyline { .. }))
        .filter(|i| matches!(i.style, Style::Cut | Style::Runout | Style::ScrewIn | Style::Tool))
        .map(|i| Item::new(i.shape.clone(), Style::Compare))
        .collect()
}

/// `scene` with `over` laid on top (its bounds grown; its focus kept).
pub fn merged(scene: &Scene, over: &[Item]) -> Scene {
    let mut out = scene.clone();
    for it in over {
        it.each_point(|p| out.bounds.add(p));
    }
    out.items.extend(over.iter().cloned());
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::Dialect;
    use crate::settings::Settings;

    #[test]
    fn the_other_programs_passes_lie_over_the_drawing() {
        let s = Settings::new(Dialect::Gsk980tdc);
        let a = crate::plan(include_str!("../../examples/o1006.nc"), &s);
        let b = crate::plan(&include_str!("../../examples/o1006.nc").replace("X45.9", "X45.85"), &s);
        let side = crate::diagram::side(&b);
        let over = items(&side);
        assert_eq!(over.len(), 5, "five cuts");
        assert!(over.iter().all(|i| i.style == Style::Compare && i.lines.is_empty()));
        let m = merged(&crate::diagram::side(&a), &over);
        assert_eq!(m.items.len(), crate::diagram::side(&a).items.len() + 5);
        let tooth = crate::diagram::tooth(&b, 0, 1).unwrap();
        assert!(items(&tooth).iter().any(|i| i.style == Style::Compare));
    }
}
