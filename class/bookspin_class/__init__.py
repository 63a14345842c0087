"""bookspin class (docs/class.md): a class's phone tosses served, stored and fitted as one body on
the teacher's laptop. One module per concept: options (the command line), addresses (the
laptop's addresses phones reach), data_folder (DATA: one server at a time, the teacher's alone,
left as found by a start that cannot serve), store (SQLite or PostgreSQL, one schema), pooled (the class's fit, bookspin.fit off the event loop), limits
(sizes, rates, slow clients, names), tls (the local certificate authority and the server's
certificate), join_screen (the QR code and the projector page), routes (the HTTP API,
docs/class.md, "The API") and server (the wiring)."""
