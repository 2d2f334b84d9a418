-- Taiwa shop server, migration 2: the job store (docs/shop-server.md).
-- A job by name, every version saved with who, station and when, and the
-- lock a station holds while it edits the job (the open mark, shop-wide).
CREATE TABLE jobs (
  name text PRIMARY KEY CHECK (length(name) BETWEEN 1 AND 200),
  locked_by text, locked_station text, locked_at timestamptz);
CREATE TABLE job_versions (
  job text NOT NULL REFERENCES jobs(name) ON DELETE CASCADE, version integer NOT NULL,
  content text NOT NULL, who text NOT NULL DEFAULT session_user,
  station text NOT NULL DEFAULT current_setting('application_name'), at timestamptz NOT NULL DEFAULT now(),
  PRIMARY KEY (job, version));
