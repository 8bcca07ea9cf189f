//! The completions and man pages in the tree are those the clap definition generates now.

use std::fs;
use std::path::Path;

#[test]
fn the_clap_definition_is_consistent() {
    mbtool::docs::command().debug_assert();
}

fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut files: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| {
            let path = entry.unwrap().path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            (name, fs::read(&path).unwrap())
        })
        .collect();
    files.sort();
    files
}

#[test]
fn completions_and_man_pages_are_in_step_with_the_cli() {
    let fresh = tempfile::tempdir().unwrap();
    mbtool::docs::generate(fresh.path()).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for dir in ["completions", "man"] {
        let want = files(&fresh.path().join(dir));
        let have = files(&root.join(dir));
        let names =
            |files: &[(String, Vec<u8>)]| files.iter().map(|f| f.0.clone()).collect::<Vec<_>>();
        assert_eq!(
            names(&have),
            names(&want),
            "{dir}/ is out of date: run `cargo run -- generate`"
        );
        for ((name, have), (_, want)) in have.iter().zip(&want) {
            assert!(
                have == want,
                "{dir}/{name} is out of date: run `cargo run -- generate`"
            );
        }
    }
}

#[test]
fn every_man_page_has_exit_status_and_examples() {
    let fresh = tempfile::tempdir().unwrap();
    mbtool::docs::write_man_pages(fresh.path()).unwrap();
    for (name, page) in files(fresh.path()) {
        let page = String::from_utf8(page).unwrap();
        assert!(page.contains(".SH \"EXIT STATUS\""), "{name}");
        assert!(page.contains(".SH EXAMPLES"), "{name} has no examples");
    }
}
