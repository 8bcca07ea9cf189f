//! The options of mbpoll and modpoll that users type out of habit, answered with mbtool's
//! spelling instead of the parser's advice (`-- -c` is never what was meant).

/// What an option of mbpoll or modpoll is, and how mbtool says it.
const OPTIONS: &[(&str, &str, &str)] = &[
    ("-a", "slave address", "here it is the first argument after the command, read-holding 17 ..."),
    ("-r", "start reference", "here it is the argument after the slave: read-holding 17 400001, or read-holding --address-base 1 17 1 to count from 1 as mbpoll does"),
    ("-c", "count", "here it is the third argument, read 17 400001 2"),
    ("-t", "data type", "here the command says it: read-coils, read-inputs, read-input-registers or read-holding (--type sets how registers are shown)"),
    ("-1", "poll once", "here a read is done once unless --poll INTERVAL is given"),
    ("-l", "poll rate", "here it is --poll 1s"),
    ("-P", "parity", "here it is --parity even|odd|none"),
    ("-0", "0-based references", "here a bare number (not 5 or 6 digits) is a 0-based protocol address unless --address-base 1 is given, and --pdu-addresses takes every number so"),
    ("-R", "RS-485 mode", "here it is --rts-toggle (mbtool moves RTS) or --rs485 (the kernel's RS-485 mode), with --rts-level high or low"),
    ("-F", "RS-485 mode", "here it is --rts-toggle (mbtool moves RTS) or --rs485 (the kernel's RS-485 mode), with --rts-level high or low"),
];

/// The mbpoll habit behind an unknown option `typed`, as a one-line message; with the
/// whole line `args` (mbtool's own words), the mbtool command that does what an mbpoll
/// line of `-a`, `-r`, `-c` and `-t` asks.
pub fn mbpoll_habit(typed: &str, args: &[String]) -> Option<String> {
    let flag = typed.split(['=', ' ']).next().unwrap_or(typed);
    let (option, what, here) = OPTIONS.iter().find(|(option, ..)| {
        flag == *option || (flag.len() > 2 && flag.starts_with(option) && option.len() == 2)
    })?;
    let mut message = format!("{option} is mbpoll's {what}: {here}");
    if let Some(command) = equivalent(args) {
        message.push_str(&format!("; the line given is {command}"));
    } else if let Some((table, shown)) = (*option == "-t")
        .then(|| value_of(args, "-t"))
        .flatten()
        .and_then(|t| mbpoll_type(&t))
    {
        message.push_str(&format!("; -t {table}:... is {shown} here"));
    }
    Some(message)
}

/// What mbpoll's `-t 4:float` reads, as mbtool says it: its table and `--type`.
fn mbpoll_type(value: &str) -> Option<(String, String)> {
    let (table, kind) = value.split_once(':').unwrap_or((value, ""));
    let command = match table {
        "0" => "read-coils",
        "1" => "read-inputs",
        "3" => "read-input-registers",
        "4" => "read-holding",
        _ => return None,
    };
    // mbpoll's int and float are 32 bits; its hex one register.
    let shown = match kind {
        "" => String::new(),
        "int" => " --type i32".into(),
        "float" => " --type f32".into(),
        "hex" => " --type hex".into(),
        _ => return None,
    };
    Some((
        table.to_string(),
        format!("{command} SLAVE REFERENCE COUNT{shown}"),
    ))
}

/// The value typed after `name`, or glued to it (`-t4:float`).
fn value_of(args: &[String], name: &str) -> Option<String> {
    args.iter()
        .enumerate()
        .find_map(|(i, word)| match word.strip_prefix(name) {
            Some("") => args.get(i + 1).cloned(),
            Some(glued) if !glued.starts_with('-') => Some(glued.to_string()),
            _ => None,
        })
}

/// `mbtool read-holding 17 400001 2` for `-a 17 -r 1 -c 2`, when `-a` is there.
fn equivalent(args: &[String]) -> Option<String> {
    let value = |name: &str| value_of(args, name);
    let slave = value("-a")?;
    // mbpoll's -r counts from 1, or from 0 after -0.
    let zero_based = args.iter().any(|word| word == "-0");
    let start: u32 = value("-r").map_or(Some(1), |r| r.parse().ok())? + u32::from(zero_based);
    let count = value("-c").unwrap_or_else(|| "1".into());
    let table = value("-t").unwrap_or_else(|| "4".into());
    let (command, digit) = match table.split(':').next()? {
        "0" => ("read-coils", 0),
        "1" => ("read-inputs", 1),
        "3" => ("read-input-registers", 3),
        "4" => ("read-holding", 4),
        _ => return None,
    };
    let reference = format!("{digit}{start:05}");
    (1..=65536)
        .contains(&start)
        .then(|| format!("mbtool {command} {slave} {reference} {count}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(line: &str) -> Vec<String> {
        line.split(' ').map(String::from).collect()
    }

    #[test]
    fn an_mbpoll_line_is_answered_with_mbtools() {
        assert_eq!(
            mbpoll_habit("-a", &words("mbtool -a 17 -r 1 -c 2 --port sim")).as_deref(),
            Some("-a is mbpoll's slave address: here it is the first argument after the command, read-holding 17 ...; the line given is mbtool read-holding 17 400001 2")
        );
        assert_eq!(
            equivalent(&words("mbtool -a 3 -t 3 -r 10 -c 4")).as_deref(),
            Some("mbtool read-input-registers 3 300010 4")
        );
        assert_eq!(
            equivalent(&words("mbtool -a3 -t0 -r5")).as_deref(),
            Some("mbtool read-coils 3 000005 1")
        );
        assert!(
            mbpoll_habit("-c", &words("mbtool read 17 400001 -c 2"))
                .is_some_and(|m| m.starts_with(
                    "-c is mbpoll's count: here it is the third argument, read 17 400001 2"
                ))
        );
        assert_eq!(
            equivalent(&words("mbtool -a 17 -0 -r 107 -c 3")).as_deref(),
            Some("mbtool read-holding 17 400108 3")
        );
        assert_eq!(mbpoll_habit("-x", &words("mbtool -x")), None);
        assert!(
            mbpoll_habit("-t", &words("mbtool read-holding 1 400001 -t 4:float"))
                .is_some_and(|m| m
                    .ends_with("; -t 4:... is read-holding SLAVE REFERENCE COUNT --type f32 here"))
        );
    }
}
