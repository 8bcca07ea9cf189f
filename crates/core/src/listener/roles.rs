//! What a client may ask of a server by the role its certificate claims (Modbus/TCP
//! Security): `--role operator=read,write:400001-400100`. A request its role does not
//! allow is answered with exception 01, illegal function, as the specification says.

use thiserror::Error;

use crate::codec::{diagnostic_only_reads, function_only_reads, Request};
use crate::model::address::{parse_reference_span, reference, Table};

/// What one right covers: everything, or some spans of the tables.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
enum Reach {
    /// Not given.
    #[default]
    Nothing,
    /// `read` or `write` alone.
    Everything,
    /// `write:400001-400100`: only these, as (table, first address, past the last).
    Spans(Vec<(Table, u32, u32)>),
}

impl Reach {
    fn covers(&self, table: Table, address: u16, count: usize) -> bool {
        let start = u32::from(address);
        let end = start + count as u32;
        match self {
            Reach::Nothing => false,
            Reach::Everything => true,
            Reach::Spans(spans) => spans
                .iter()
                .any(|&(t, first, past)| t == table && first <= start && end <= past),
        }
    }

    fn is_everything(&self) -> bool {
        *self == Reach::Everything
    }

    fn add(&mut self, span: Option<(Table, u32, u32)>) {
        match (span, &mut *self) {
            (_, Reach::Everything) => {}
            (None, _) => *self = Reach::Everything,
            (Some(span), Reach::Spans(spans)) => spans.push(span),
            (Some(span), Reach::Nothing) => *self = Reach::Spans(vec![span]),
        }
    }
}

/// One role: its name and what it may read and write.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Role {
    /// As certificates carry it.
    pub name: String,
    read: Reach,
    write: Reach,
}

/// Why a `--role` text is no role.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("{text}: {why}")]
pub struct RoleError {
    text: String,
    why: String,
}

impl Role {
    /// `NAME=RULES`, the rules `read` and `write`, each alone (everything) or with a
    /// reference range (`write:400001-400100`), separated by commas.
    pub fn parse(text: &str) -> Result<Role, RoleError> {
        let fail = |why: String| RoleError {
            text: format!("--role {text}"),
            why,
        };
        let (name, rules) = text.split_once('=').ok_or_else(|| {
            fail("give NAME=RULES, as in operator=read,write:400001-400100".into())
        })?;
        let name = name.trim();
        if name.is_empty() {
            return Err(fail("the role has no name before '='".into()));
        }
        let mut role = Role {
            name: name.to_string(),
            read: Reach::Nothing,
            write: Reach::Nothing,
        };
        for rule in rules.split(',').map(str::trim) {
            let (right, range) = match rule.split_once(':') {
                Some((right, range)) => (right, Some(range)),
                None => (rule, None),
            };
            let span = match range {
                None => None,
                Some(range) => {
                    let span =
                        parse_reference_span(range).map_err(|e| fail(format!("'{range}': {e}")))?;
                    let first = u32::from(span.address);
                    Some((span.table, first, first + span.count.unwrap_or(1)))
                }
            };
            match right {
                "read" => role.read.add(span),
                "write" => {
                    if let Some((Table::DiscreteInputs | Table::InputRegisters, ..)) = span {
                        return Err(fail(format!(
                            "'{rule}': discrete inputs and input registers cannot be written"
                        )));
                    }
                    role.write.add(span);
                }
                "" => return Err(fail("an empty rule: give read or write".into())),
                other => {
                    return Err(fail(format!(
                        "'{other}' is no right: give read or write, each with a range or alone"
                    )))
                }
            }
        }
        Ok(role)
    }

    /// Whether this role may make `request`.
    pub fn allows(&self, request: &Request) -> bool {
        self.refusal(request).is_none()
    }

    /// Why this role may not make `request` (`role viewer may not write 400001`), or
    /// `None` when it may. Reads and writes of the tables need their right over every
    /// address they touch; a diagnostic that only reads needs `read` over everything, one
    /// that changes the device (restart, clear counters, listen only) and the functions
    /// without addresses that write (file records) need `write` over everything, and a
    /// function mbtool does not know needs both.
    pub fn refusal(&self, request: &Request) -> Option<String> {
        use Request as R;
        let (read, write) = (&self.read, &self.write);
        let span = |right: &Reach, verb: &str, table: Table, address: u16, count: usize| {
            (!right.covers(table, address, count)).then(|| {
                let first = reference(table, address);
                match count {
                    0 | 1 => format!("{verb} {}", first.as_str()),
                    n => {
                        let last = reference(table, address.saturating_add(n as u16 - 1));
                        format!("{verb} {}-{}", first.as_str(), last.as_str())
                    }
                }
            })
        };
        let whole = |needs_read: bool, needs_write: bool| {
            let lacks_read = needs_read && !read.is_everything();
            let lacks_write = needs_write && !write.is_everything();
            let needs = match (lacks_read, lacks_write) {
                (false, false) => return None,
                (true, true) => "read and write",
                (true, false) => "read",
                (false, true) => "write",
            };
            Some(format!(
                "use function {:02} ({}), which needs {needs} over every address",
                request.function(),
                crate::codec::function::name(request.function())
            ))
        };
        let why = match request {
            R::ReadCoils { address, quantity } => {
                span(read, "read", Table::Coils, *address, usize::from(*quantity))
            }
            R::ReadDiscreteInputs { address, quantity } => span(
                read,
                "read",
                Table::DiscreteInputs,
                *address,
                usize::from(*quantity),
            ),
            R::ReadHoldingRegisters { address, quantity } => span(
                read,
                "read",
                Table::HoldingRegisters,
                *address,
                usize::from(*quantity),
            ),
            R::ReadInputRegisters { address, quantity } => span(
                read,
                "read",
                Table::InputRegisters,
                *address,
                usize::from(*quantity),
            ),
            R::WriteSingleCoil { address, .. } => span(write, "write", Table::Coils, *address, 1),
            R::WriteMultipleCoils { address, values } => {
                span(write, "write", Table::Coils, *address, values.len())
            }
            R::WriteSingleRegister { address, .. } | R::MaskWriteRegister { address, .. } => {
                span(write, "write", Table::HoldingRegisters, *address, 1)
            }
            R::WriteMultipleRegisters { address, values } => span(
                write,
                "write",
                Table::HoldingRegisters,
                *address,
                values.len(),
            ),
            R::ReadWriteMultipleRegisters {
                read_address,
                read_quantity,
                write_address,
                values,
            } => span(
                read,
                "read",
                Table::HoldingRegisters,
                *read_address,
                usize::from(*read_quantity),
            )
            .or_else(|| {
                span(
                    write,
                    "write",
                    Table::HoldingRegisters,
                    *write_address,
                    values.len(),
                )
            }),
            R::Diagnostics { sub_function, .. } if diagnostic_only_reads(*sub_function) => {
                whole(true, false)
            }
            R::Diagnostics { .. } => whole(false, true),
            R::ReadExceptionStatus
            | R::ReportServerId
            | R::ReadDeviceIdentification { .. }
            | R::ReadFileRecord { .. }
            | R::ReadFifoQueue { .. } => whole(true, false),
            R::WriteFileRecord { .. } => whole(false, true),
            R::Other { function, .. } if function_only_reads(*function) => whole(true, false),
            // File record write.
            R::Other { function: 0x15, .. } => whole(false, true),
            R::Other { .. } => whole(true, true),
        };
        why.map(|why| format!("role {} may not {why}", self.name))
    }
}

/// The roles a server knows, and the one it gives a client whose certificate claims
/// none.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Roles {
    roles: Vec<Role>,
    default: Option<String>,
}

impl Roles {
    /// Roles from their `--role` texts and `--default-role`, which must be one of them.
    pub fn new(texts: &[String], default: Option<&str>) -> Result<Roles, RoleError> {
        let roles = texts
            .iter()
            .map(|text| Role::parse(text))
            .collect::<Result<Vec<_>, _>>()?;
        for (i, role) in roles.iter().enumerate() {
            if roles[..i].iter().any(|earlier| earlier.name == role.name) {
                return Err(RoleError {
                    text: format!("--role {}", texts[i]),
                    why: format!(
                        "role '{}' is given twice: give it once, all its rules together",
                        role.name
                    ),
                });
            }
        }
        if let Some(default) = default {
            if !roles.iter().any(|role| role.name == default) {
                return Err(RoleError {
                    text: format!("--default-role {default}"),
                    why: format!("'{default}' is none of the roles given with --role"),
                });
            }
        }
        Ok(Roles {
            roles,
            default: default.map(str::to_string),
        })
    }

    /// The role called `name`, if one was given.
    pub fn named(&self, name: &str) -> Option<&Role> {
        self.roles.iter().find(|role| role.name == name)
    }

    /// Whether roles are checked at all: without `--role`, every client may do anything.
    pub fn checked(&self) -> bool {
        !self.roles.is_empty()
    }

    /// The role a client gets: the one its certificate claims (`None`: claims none), or
    /// the default; `Err` with why, when the client is to be refused.
    pub fn for_client(&self, claimed: Option<&str>) -> Result<Option<&Role>, String> {
        if !self.checked() {
            return Ok(None);
        }
        let name = match (claimed, &self.default) {
            (Some(name), _) => name,
            (None, Some(default)) => default,
            (None, None) => {
                return Err(
                    "its certificate carries no role, and there is no --default-role".into(),
                )
            }
        };
        match self.named(name) {
            Some(role) => Ok(Some(role)),
            None => Err(format!(
                "its role '{name}' is none of the roles given with --role"
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(address: u16, quantity: u16) -> Request {
        Request::ReadHoldingRegisters { address, quantity }
    }

    fn write(address: u16, value: u16) -> Request {
        Request::WriteSingleRegister { address, value }
    }

    #[test]
    fn an_operator_writes_inside_its_range_only() {
        let operator = Role::parse("operator=read,write:400001-400100").unwrap();
        assert!(operator.allows(&read(500, 10)));
        assert!(operator.allows(&write(0, 1)));
        assert!(operator.allows(&write(99, 1)));
        assert!(!operator.allows(&write(100, 1)));
        assert!(!operator.allows(&Request::WriteMultipleRegisters {
            address: 98,
            values: vec![1, 2, 3]
        }));
        assert!(!operator.allows(&Request::WriteSingleCoil {
            address: 0,
            value: true
        }));
        assert!(operator.allows(&Request::ReportServerId));
    }

    #[test]
    fn a_viewer_reads_and_never_writes() {
        let viewer = Role::parse("viewer=read").unwrap();
        assert!(viewer.allows(&read(0, 125)));
        assert!(!viewer.allows(&write(0, 1)));
        assert!(viewer.allows(&Request::Diagnostics {
            sub_function: 0,
            data: vec![1, 2]
        }));
        // Clearing the counters changes the device.
        assert!(!viewer.allows(&Request::Diagnostics {
            sub_function: 0x0A,
            data: vec![0, 0]
        }));
        assert!(!viewer.allows(&Request::Other {
            function: 0x41,
            data: vec![]
        }));
    }

    #[test]
    fn a_refusal_says_which_role_and_what_it_may_not_do() {
        let viewer = Role::parse("Viewer=read:400001-400010").unwrap();
        assert_eq!(
            viewer.refusal(&write(0, 1)).as_deref(),
            Some("role Viewer may not write 400001")
        );
        assert_eq!(
            viewer.refusal(&read(499, 2)).as_deref(),
            Some("role Viewer may not read 400500-400501")
        );
        assert_eq!(
            viewer
                .refusal(&Request::Diagnostics {
                    sub_function: 1,
                    data: vec![0, 0]
                })
                .as_deref(),
            Some("role Viewer may not use function 08 (Diagnostics), which needs write over every address")
        );
        assert_eq!(viewer.refusal(&read(0, 10)), None);
    }

    #[test]
    fn a_read_range_limits_reads() {
        let role = Role::parse("logger=read:300001-300010").unwrap();
        assert!(role.allows(&Request::ReadInputRegisters {
            address: 0,
            quantity: 10
        }));
        assert!(!role.allows(&Request::ReadInputRegisters {
            address: 5,
            quantity: 10
        }));
        assert!(!role.allows(&read(0, 1)));
        assert!(!role.allows(&Request::ReportServerId));
    }

    #[test]
    fn bad_roles_are_refused_with_why() {
        for (text, why) in [
            ("operator", "NAME=RULES"),
            ("=read", "no name"),
            ("x=delete", "no right"),
            ("x=read,", "empty rule"),
            ("x=write:300001-300002", "cannot be written"),
            ("x=read:999999", "'999999'"),
        ] {
            let error = Role::parse(text).unwrap_err().to_string();
            assert!(error.contains(why), "{text}: {error}");
        }
        let twice = Roles::new(&["a=read".into(), "a=write".into()], None);
        assert!(twice.unwrap_err().to_string().contains("twice"));
        let unknown = Roles::new(&["a=read".into()], Some("b"));
        assert!(unknown
            .unwrap_err()
            .to_string()
            .contains("none of the roles"));
    }

    #[test]
    fn a_client_without_a_role_gets_the_default_or_is_refused() {
        let roles =
            Roles::new(&["viewer=read".into(), "operator=read,write".into()], None).unwrap();
        assert!(roles.for_client(None).is_err());
        assert_eq!(
            roles.for_client(Some("viewer")).unwrap().unwrap().name,
            "viewer"
        );
        assert!(roles.for_client(Some("admin")).is_err());
        let with_default = Roles::new(&["viewer=read".into()], Some("viewer")).unwrap();
        assert_eq!(
            with_default.for_client(None).unwrap().unwrap().name,
            "viewer"
        );
        assert_eq!(Roles::default().for_client(None), Ok(None));
    }
}
