//! The requests of many clients waiting for one line: each client's in the order it sent
//! them, the clients taken in turn, so that one that pipelines a thousand requests delays
//! another's single request by one transaction at most.

use std::collections::{HashMap, VecDeque};
use std::sync::{Condvar, Mutex};

use crate::listener::clients::lock;

/// A client's place in the queue.
pub(crate) type ClientId = usize;

/// How many requests one client may have waiting; past this its reading pauses, so that a
/// client cannot fill memory (TCP then holds back its requests).
pub(crate) const MAX_WAITING_PER_CLIENT: usize = 1024;

/// Requests waiting, by client, and the turn of the clients that have some.
pub(crate) struct FairQueue<T> {
    state: Mutex<State<T>>,
    /// Told when a request comes and when a client's requests are taken or dropped.
    changed: Condvar,
}

struct State<T> {
    waiting: HashMap<ClientId, VecDeque<T>>,
    /// The clients with requests waiting, the next to be served first.
    turn: VecDeque<ClientId>,
    /// The client whose request is on the line.
    in_flight: Option<ClientId>,
}

impl<T> FairQueue<T> {
    pub(crate) fn new() -> Self {
        Self {
            state: Mutex::new(State {
                waiting: HashMap::new(),
                turn: VecDeque::new(),
                in_flight: None,
            }),
            changed: Condvar::new(),
        }
    }

    /// Adds `client`'s request behind its others; waits while it has too many waiting.
    pub(crate) fn push(&self, client: ClientId, item: T) {
        let mut state = lock(&self.state);
        while state
            .waiting
            .get(&client)
            .is_some_and(|queue| queue.len() >= MAX_WAITING_PER_CLIENT)
        {
            state = match self.changed.wait(state) {
                Ok(state) => state,
                Err(poisoned) => poisoned.into_inner(),
            };
        }
        let queue = state.waiting.entry(client).or_default();
        queue.push_back(item);
        // A client whose request is on the line takes its next turn when that one ends.
        if queue.len() == 1 && state.in_flight != Some(client) {
            state.turn.push_back(client);
        }
        drop(state);
        self.changed.notify_all();
    }

    /// The next request: the oldest of the client whose turn it is. Waits for one. It is
    /// in flight until [`FairQueue::finished`].
    pub(crate) fn pop(&self) -> (ClientId, T) {
        let mut state = lock(&self.state);
        loop {
            if let Some(taken) = state.take_next() {
                state.in_flight = Some(taken.0);
                drop(state);
                self.changed.notify_all();
                return taken;
            }
            state = match self.changed.wait(state) {
                Ok(state) => state,
                Err(poisoned) => poisoned.into_inner(),
            };
        }
    }

    /// The request taken last has been answered: its client, if it has more waiting,
    /// goes behind every client that asked meanwhile.
    pub(crate) fn finished(&self) {
        let mut state = lock(&self.state);
        if let Some(client) = state.in_flight.take() {
            if state.waiting.contains_key(&client) {
                state.turn.push_back(client);
            }
        }
        drop(state);
        self.changed.notify_all();
    }

    /// Waits until every request of `client` has been answered: a client that closed its
    /// sending side still reads its answers.
    pub(crate) fn wait_until_served(&self, client: ClientId) {
        let mut state = lock(&self.state);
        while state.waiting.contains_key(&client) || state.in_flight == Some(client) {
            state = match self.changed.wait(state) {
                Ok(state) => state,
                Err(poisoned) => poisoned.into_inner(),
            };
        }
    }

    /// Drops what `client` has waiting: it has gone.
    pub(crate) fn forget(&self, client: ClientId) {
        let mut state = lock(&self.state);
        state.waiting.remove(&client);
        state.turn.retain(|c| *c != client);
        drop(state);
        self.changed.notify_all();
    }
}

impl<T> State<T> {
    fn take_next(&mut self) -> Option<(ClientId, T)> {
        let client = self.turn.pop_front()?;
        let queue = self.waiting.get_mut(&client)?;
        let item = queue.pop_front()?;
        if queue.is_empty() {
            self.waiting.remove(&client);
        }
        Some((client, item))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clients_take_turns_and_each_keeps_its_order() {
        let queue = FairQueue::new();
        for n in 0..1000 {
            queue.push(1, ("a", n));
        }
        queue.push(2, ("b", 0));
        queue.push(3, ("c", 0));
        queue.push(2, ("b", 1));
        let order: Vec<(ClientId, (&str, i32))> = (0..6)
            .map(|_| {
                let taken = queue.pop();
                queue.finished();
                taken
            })
            .collect();
        assert_eq!(
            order,
            [
                (1, ("a", 0)),
                (2, ("b", 0)),
                (3, ("c", 0)),
                (1, ("a", 1)),
                (2, ("b", 1)),
                (1, ("a", 2)),
            ]
        );
        // The pipelining client's rest stays in order.
        assert!((3..1000).all(|n| {
            let taken = queue.pop();
            queue.finished();
            taken == (1, ("a", n))
        }));
    }

    #[test]
    fn a_client_that_asks_during_a_transaction_goes_before_the_next_of_its_client() {
        let queue = FairQueue::new();
        for n in 0..10 {
            queue.push(1, n);
        }
        assert_eq!(queue.pop(), (1, 0));
        // Client 2 asks while client 1's first request is on the line.
        queue.push(2, 100);
        queue.finished();
        assert_eq!(queue.pop(), (2, 100));
        queue.finished();
        assert_eq!(queue.pop(), (1, 1));
    }

    #[test]
    fn a_client_is_served_once_its_requests_are_answered() {
        let queue = std::sync::Arc::new(FairQueue::new());
        queue.push(1, 10);
        queue.push(1, 11);
        let waiter = {
            let queue = std::sync::Arc::clone(&queue);
            std::thread::spawn(move || queue.wait_until_served(1))
        };
        for _ in 0..2 {
            std::thread::sleep(std::time::Duration::from_millis(20));
            assert!(!waiter.is_finished());
            if queue.pop() == (1, 10) {
                queue.finished();
            }
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
        assert!(
            !waiter.is_finished(),
            "the last request is still on the line"
        );
        queue.finished();
        waiter.join().unwrap();
    }

    #[test]
    fn a_client_that_left_is_not_served() {
        let queue = FairQueue::new();
        queue.push(1, 10);
        queue.push(1, 11);
        queue.push(2, 20);
        queue.forget(1);
        assert_eq!(queue.pop(), (2, 20));
        queue.finished();
        queue.push(1, 12);
        assert_eq!(queue.pop(), (1, 12));
    }

    #[test]
    fn a_client_with_too_many_waiting_is_held_until_one_is_taken() {
        let queue = std::sync::Arc::new(FairQueue::new());
        for n in 0..MAX_WAITING_PER_CLIENT {
            queue.push(1, n);
        }
        let pusher = {
            let queue = std::sync::Arc::clone(&queue);
            std::thread::spawn(move || queue.push(1, MAX_WAITING_PER_CLIENT))
        };
        std::thread::sleep(std::time::Duration::from_millis(50));
        assert!(!pusher.is_finished(), "the push should wait for room");
        assert_eq!(queue.pop(), (1, 0));
        queue.finished();
        pusher.join().unwrap();
        let mut last = 0;
        for _ in 1..=MAX_WAITING_PER_CLIENT {
            last = queue.pop().1;
            queue.finished();
        }
        assert_eq!(last, MAX_WAITING_PER_CLIENT);
    }
}
