-- Taiwa shop server: the stations' group roles, run once by the
-- administrator as the database's owner (docs/shop-server.md, "Roles"):
--   psql -d taiwa -f /usr/share/taiwa/db/roles.sql
-- Not a migration (roles belong to the whole server, not to the database).
-- A station's login role is then made a member of the groups it needs:
--   CREATE ROLE office LOGIN IN ROLE taiwa_tool_writer, taiwa_job_writer;
DO $$
BEGIN
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'taiwa_tool_reader') THEN
    CREATE ROLE taiwa_tool_reader NOLOGIN;
  END IF;
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'taiwa_tool_writer') THEN
    CREATE ROLE taiwa_tool_writer NOLOGIN;
  END IF;
  IF NOT EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'taiwa_job_writer') THEN
    CREATE ROLE taiwa_job_writer NOLOGIN;
  END IF;
END $$;
SELECT taiwa_grant_roles();
