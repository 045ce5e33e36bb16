"""rig-scope: the rig's live dashboard (rig/scope/README.md). view.py turns the LCM messages of
one rig (one channel prefix) into what the page draws; server.py receives udpm and serves the
page on 127.0.0.1; main.py is the command line."""
