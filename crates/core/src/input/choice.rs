//! Settings picked by name (`--type f32`, `--order CDAB`, `--parity even`): each lists its
//! names with a line of help, and reads a name back whatever its case, so that a front end
//! can offer them without the core knowing it.

/// A setting with a fixed set of named choices.
pub trait Choice: Copy + Sized + 'static {
    /// Every choice, in the order they are listed.
    const ALL: &'static [Self];

    /// The name the user types.
    fn name(self) -> &'static str;

    /// A line saying what the choice means, where its name does not.
    fn help(self) -> Option<&'static str> {
        None
    }

    /// Other tools' names for it (`float` for `f32`), taken as well.
    fn aliases(self) -> &'static [&'static str] {
        &[]
    }

    /// The choice a name stands for, in any case.
    fn from_name(name: &str) -> Option<Self> {
        Self::ALL.iter().copied().find(|choice| {
            choice.name().eq_ignore_ascii_case(name)
                || choice
                    .aliases()
                    .iter()
                    .any(|alias| alias.eq_ignore_ascii_case(name))
        })
    }
}
