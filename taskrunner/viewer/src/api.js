// Talking to the taskrunner API: the token as a bearer header (never in a URL), JSON in
// and out, and Server-Sent Events read with fetch (EventSource cannot send headers).

const TOKEN_KEY = 'taskrunner.token';

export function getToken() {
  return sessionStorage.getItem(TOKEN_KEY) || '';
}

export function setToken(token) {
  if (token) sessionStorage.setItem(TOKEN_KEY, token);
  else sessionStorage.removeItem(TOKEN_KEY);
}

export class ApiError extends Error {
  constructor(status, detail) {
    super(typeof detail === 'string' ? detail : JSON.stringify(detail));
    this.status = status;
    this.detail = detail;
  }
}

function headers(extra) {
  const h = Object.assign({}, extra || {});
  const token = getToken();
  if (token) h.Authorization = 'Bearer ' + token;
  return h;
}

export async function request(method, path, body, signal) {
  const init = { method, headers: headers(body !== undefined ? { 'content-type': 'application/json' } : {}), signal };
  if (body !== undefined) init.body = JSON.stringify(body);
  const answer = await fetch(path, init);
  const text = await answer.text();
  let data = null;
  try { data = text ? JSON.parse(text) : null; } catch (e) { data = text; }
  if (!answer.ok) {
    const detail = data && data.detail !== undefined ? data.detail : (data || answer.statusText);
    throw new ApiError(answer.status, detail);
  }
  return data;
}

export const get = (path, signal) => request('GET', path, undefined, signal);
export const post = (path, body, signal) => request('POST', path, body === undefined ? {} : body, signal);

export async function getBinary(path) {
  const answer = await fetch(path, { headers: headers() });
  if (!answer.ok) throw new ApiError(answer.status, answer.statusText + ' ' + path);
  return answer.arrayBuffer();
}

// Follow a run's events: onEvent(event) for each, resumes after a dropped connection
// from the last seq seen; ends after run_finished or when the signal aborts.
export async function followEvents(runId, onEvent, signal) {
  let last = 0;
  for (let attempt = 0; attempt < 50 && !signal.aborted; attempt++) {
    let finished = false;
    try {
      const answer = await fetch(`/runs/${encodeURIComponent(runId)}/events?after=${last}`,
        { headers: headers({ Accept: 'text/event-stream' }), signal });
      if (!answer.ok) throw new ApiError(answer.status, await answer.text());
      const reader = answer.body.getReader();
      const decoder = new TextDecoder();
      let buffer = '';
      for (;;) {
        const { value, done } = await reader.read();
        if (done) break;
        buffer += decoder.decode(value, { stream: true });
        let cut;
        while ((cut = buffer.search(/\r?\n\r?\n/)) >= 0) {
          const block = buffer.slice(0, cut);
          buffer = buffer.slice(cut).replace(/^\r?\n\r?\n/, '');
          const data = block.split(/\r?\n/).filter((l) => l.startsWith('data:'))
            .map((l) => l.slice(5).replace(/^ /, '')).join('\n');
          if (!data) continue;
          const event = JSON.parse(data);
          last = Math.max(last, event.seq);
          onEvent(event);
          if (event.kind === 'run_finished') finished = true;
        }
      }
      if (finished) return;
    } catch (err) {
      if (signal.aborted) return;
      if (err instanceof ApiError && err.status < 500) throw err;
    }
    await new Promise((r) => setTimeout(r, 500));
  }
}
