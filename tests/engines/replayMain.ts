// Entry of the cross-engine replay bundle (tests/engines.test.ts): plays the replay recorded in Node,
// inlined at build time as REPLAY_TEXT, and prints the hash of its events.
import { playSession } from './scenarios.js'

declare const REPLAY_TEXT: string
console.log(JSON.stringify(playSession(REPLAY_TEXT)))
