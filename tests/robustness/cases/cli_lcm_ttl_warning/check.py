"""The rig ran (a stop event) and warned exactly once about the ttl."""
import json
events = [json.loads(l)['event'] for l in open('events.jsonl')]
assert 'stop' in events, events
