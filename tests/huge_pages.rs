#![cfg(target_os = "linux")]
//! A large program's motion buffer asks the kernel for huge pages
//! (`src/huge.rs`): `hg` in the flags of its mapping, as proc(5) lists them
//! in `/proc/self/smaps` ("hg - huge page advise flag"). A small one's does not.

use screwcut::assemble::Assembler;
use screwcut::{Dialect, Settings};

/// The `VmFlags` of the mapping holding `addr`.
fn flags_at(addr: usize) -> Option<String> {
    let smaps = std::fs::read_to_string("/proc/self/smaps").ok()?;
    let mut inside = false;
    for line in smaps.lines() {
        let head = line.split_whitespace().next().unwrap_or("");
        if let Some((a, b)) = head.split_once('-')
            && let (Ok(a), Ok(b)) = (usize::from_str_radix(a, 16), usize::from_str_radix(b, 16))
        {
            inside = (a..b).contains(&addr);
        } else if inside && let Some(f) = line.strip_prefix("VmFlags:") {
            return Some(f.to_string());
        }
    }
    None
}

#[test]
fn a_large_plans_motions_ask_for_huge_pages() {
    if !std::path::Path::new("/sys/kernel/mm/transparent_hugepage/enabled").exists() {
        return; // a kernel without transparent huge pages: nothing to ask
    }
    let s = Settings::new(Dialect::Gsk980tdc);
    let large = Assembler::new(&s, 10 << 20);
    let flags = flags_at(large.moves.as_ptr() as usize + (1 << 20)).expect("the buffer's mapping");
    assert!(flags.split_whitespace().any(|f| f == "hg"), "{flags}");
    let small = Assembler::new(&s, 1 << 10);
    let flags = flags_at(small.moves.as_ptr() as usize).expect("the buffer's mapping");
    assert!(!flags.split_whitespace().any(|f| f == "hg"), "{flags}");
}
