//! Rows as InfluxDB line protocol, written to an InfluxDB server over HTTP: the 1.x
//! `/write?db=NAME` API or the 2.x `/api/v2/write?org=ORG&bucket=BUCKET` API with a
//! token, as the URL gives it. Batches of at most 5000 lines; a server that
//! is down or refuses is asked again, waiting longer each time up to 10 s, the rows kept in
//! the buffer meanwhile.

use std::time::{Duration, Instant};

use super::{Buffer, Delivered};

/// Lines a request carries at most, as InfluxDB advises.
const BATCH: usize = 5000;

/// How long a request may take.
const REQUEST_TIMEOUT: Duration = Duration::from_secs(5);

/// The longest wait before asking a server that failed again.
const LONGEST_WAIT: Duration = Duration::from_secs(10);

/// How long the rows left at the end are tried for, with a server that is down.
const LAST_TRY: Duration = Duration::from_secs(3);

/// An InfluxDB server's write API, and the token it is asked with.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InfluxServer {
    /// `http://HOST:8086/write?db=NAME` (1.x) or
    /// `http://HOST:8086/api/v2/write?org=ORG&bucket=BUCKET` (2.x).
    pub url: String,
    /// Sent as `Authorization: Token TOKEN`: 2.x's API token, or 1.x's `USER:PASSWORD`.
    pub token: Option<String>,
}

impl InfluxServer {
    /// The `Authorization` header: 2.x's `Token TOKEN`; for the 1.x API a `USER:PASSWORD`
    /// as HTTP Basic authentication, which every 1.x server takes (1.8's `Token` is not
    /// known before it).
    fn authorization(&self) -> Option<String> {
        use base64::Engine;
        let token = self.token.as_deref()?;
        let v1 = !self
            .url
            .split('?')
            .next()
            .unwrap_or("")
            .contains("/api/v2/");
        Some(match token.split_once(':') {
            Some(_) if v1 => format!(
                "Basic {}",
                base64::engine::general_purpose::STANDARD.encode(token)
            ),
            _ => format!("Token {token}"),
        })
    }
}

/// Checks the URL of `--influx` with the token given (`INFLUX_TOKEN`): the 1.x API
/// names its database, the 2.x API its bucket and organisation and needs a token.
pub fn server(url: &str, token: Option<String>) -> Result<InfluxServer, String> {
    let give = "give the server's write URL, http://HOST:8086/write?db=NAME (1.x) or http://HOST:8086/api/v2/write?org=ORG&bucket=BUCKET (2.x)";
    let Some((place, query)) = url.split_once('?') else {
        return Err(format!("--influx {url}: {give}"));
    };
    let keys: Vec<&str> = query
        .split('&')
        .filter_map(|pair| pair.split_once('=').filter(|(_, v)| !v.is_empty()))
        .map(|(key, _)| key)
        .collect();
    let scheme = place.starts_with("http://") || place.starts_with("https://");
    let token = token.filter(|t| !t.is_empty());
    match place.trim_end_matches('/') {
        _ if !scheme => Err(format!("--influx {url}: {give}")),
        path if path.ends_with("/api/v2/write") => {
            if !keys.contains(&"bucket") || !keys.contains(&"org") {
                return Err(format!(
                    "--influx {url}: the 2.x API needs org=ORG&bucket=BUCKET in the URL"
                ));
            }
            if token.is_none() {
                return Err(format!(
                    "--influx {url}: the 2.x API needs a token: set INFLUX_TOKEN"
                ));
            }
            Ok(InfluxServer {
                url: url.to_string(),
                token,
            })
        }
        path if path.ends_with("/write") && keys.contains(&"db") => Ok(InfluxServer {
            url: url.to_string(),
            token,
        }),
        _ => Err(format!("--influx {url}: {give}")),
    }
}

/// Sends the buffer's rows to `url` until the buffer is closed and empty (or its last rows
/// could not be sent within a few seconds); `tell` is told when the server goes down and
/// comes back.
pub fn send(server: &InfluxServer, buffer: &Buffer<String>, tell: impl Fn(&str)) -> Delivered {
    let url = server.url.as_str();
    let config = ureq::Agent::config_builder()
        .timeout_global(Some(REQUEST_TIMEOUT))
        .http_status_as_error(false)
        .build();
    let agent: ureq::Agent = config.into();
    // The statuses of refusals told already: each is told once, then counted.
    let mut refusals: Vec<u16> = Vec::new();
    let mut delivered = Delivered::default();
    let mut wait = Duration::from_millis(250);
    let mut down_since: Option<Instant> = None;
    let mut closed_at: Option<Instant> = None;
    loop {
        let (rows, closing) = buffer.oldest(BATCH, Duration::from_secs(1));
        if closing {
            closed_at.get_or_insert_with(|| buffer.closed_at().unwrap_or_else(Instant::now));
        }
        if rows.is_empty() {
            if closing {
                break;
            }
            continue;
        }
        let body = rows.join("\n") + "\n";
        // At the end, no request outlasts the last try.
        let left = closed_at.map(|at| LAST_TRY.saturating_sub(at.elapsed()));
        let mut request = agent
            .post(url)
            .config()
            .timeout_global(Some(
                left.unwrap_or(REQUEST_TIMEOUT)
                    .max(Duration::from_millis(100)),
            ))
            .build();
        if let Some(authorization) = server.authorization() {
            request = request.header("Authorization", authorization);
        }
        let sent = request.send(body.as_bytes()).map(|mut response| {
            let status = response.status();
            match status.is_client_error() || status.is_server_error() {
                // What the server says is wrong, as it says it (InfluxDB's JSON error).
                true => Err((
                    status.as_u16(),
                    response
                        .body_mut()
                        .with_config()
                        .limit(1000)
                        .read_to_string()
                        .unwrap_or_default(),
                )),
                false => Ok(()),
            }
        });
        let down = match sent {
            Ok(Ok(())) => {
                buffer.sent(rows.len());
                delivered.sent += rows.len() as u64;
                wait = Duration::from_millis(250);
                if down_since.take().is_some() {
                    tell(&format!("InfluxDB at {url} takes rows again"));
                }
                None
            }
            // A server that refuses the rows themselves (a field of another type than
            // before, a database that is not there, a login it does not take) would
            // refuse them again: they are dropped and counted, and each kind of refusal
            // told once.
            Ok(Err((code, said))) if (400..500).contains(&code) => {
                buffer.sent(rows.len());
                delivered.refused += rows.len() as u64;
                if !refusals.contains(&code) {
                    refusals.push(code);
                    let said = said.trim();
                    tell(&format!(
                        "InfluxDB at {url} refused {} with status {code}{}; the rows it refuses are dropped, and counted at the end",
                        crate::output::plural(rows.len(), "row"),
                        if said.is_empty() { String::new() } else { format!(" ({said})") }
                    ));
                }
                None
            }
            Ok(Err((code, _))) => Some(format!("status {code}")),
            Err(error) => Some(error.to_string()),
        };
        if let Some(why) = down {
            if down_since.is_none() {
                down_since = Some(Instant::now());
                tell(&format!(
                    "InfluxDB at {url} does not take rows ({why}); keeping them to send when it does"
                ));
            }
            if closed_at.is_some_and(|at| at.elapsed() >= LAST_TRY) {
                break;
            }
            match closed_at {
                Some(at) => std::thread::sleep(wait.min(LAST_TRY.saturating_sub(at.elapsed()))),
                None => buffer.rest(wait),
            }
            // At the end the rows left are tried again soon, for a few seconds.
            let longest = match closed_at {
                Some(_) => Duration::from_millis(500),
                None => LONGEST_WAIT,
            };
            wait = (wait * 2).min(longest);
        }
    }
    let (dropped, unsent) = buffer.counts();
    delivered.dropped = dropped;
    delivered.unsent = unsent;
    delivered
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_1x_login_is_basic_authentication_and_a_2x_token_a_token() {
        let v1 = server("http://h:8086/write?db=plant", Some("bob:pw".into())).unwrap();
        assert_eq!(v1.authorization().as_deref(), Some("Basic Ym9iOnB3"));
        let v2 = "http://h:8086/api/v2/write?org=o&bucket=b";
        let v2 = server(v2, Some("abc:def".into())).unwrap();
        assert_eq!(v2.authorization().as_deref(), Some("Token abc:def"));
        let plain = server("http://h:8086/write?db=plant", None).unwrap();
        assert_eq!(plain.authorization(), None);
    }

    #[test]
    fn the_url_names_a_database_or_a_bucket_and_the_2x_api_needs_a_token() {
        let token = || Some("t0ken".to_string());
        assert!(server("http://127.0.0.1:8086/write?db=plant", None).is_ok());
        assert!(server("https://h:8086/write?db=plant&u=a&p=b", None).is_ok());
        let v2 = "http://127.0.0.1:8086/api/v2/write?org=site&bucket=plant";
        assert_eq!(
            server(v2, token()),
            Ok(InfluxServer {
                url: v2.into(),
                token: token()
            })
        );
        let needs = server(v2, Some(String::new())).unwrap_err();
        assert!(
            needs.ends_with("the 2.x API needs a token: set INFLUX_TOKEN"),
            "{needs}"
        );
        let bucket = "http://h:8086/api/v2/write?org=site";
        assert!(server(bucket, token())
            .unwrap_err()
            .contains("org=ORG&bucket=BUCKET"));
        for bad in [
            "http://h:8086/write",
            "http://h:8086/write?db=",
            "h:8086/write?db=x",
        ] {
            assert!(server(bad, None)
                .unwrap_err()
                .contains("give the server's write URL"));
        }
    }
}
