-- Taiwa shop server, migration 3: the rights of the stations' roles
-- (docs/shop-server.md, "Roles"). The change log is written only by the
-- trigger (security definer), never directly by a station; the grants go to
-- the three group roles roles.sql creates, when they exist, and roles.sql
-- calls taiwa_grant_roles() again after creating them, so either order works.
ALTER FUNCTION taiwa_tools_changed() SECURITY DEFINER SET search_path = public;
CREATE FUNCTION taiwa_grant_roles() RETURNS void LANGUAGE plpgsql AS $$
BEGIN
  IF EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'taiwa_tool_reader') THEN
    GRANT SELECT ON tools, cutting_data, tool_names, holders, tool_changes, taiwa_schema TO taiwa_tool_reader;
  END IF;
  IF EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'taiwa_tool_writer') THEN
    GRANT SELECT ON tools, cutting_data, tool_names, holders, tool_changes, taiwa_schema TO taiwa_tool_writer;
    GRANT INSERT, UPDATE, DELETE ON tools, cutting_data, tool_names, holders TO taiwa_tool_writer;
  END IF;
  IF EXISTS (SELECT 1 FROM pg_roles WHERE rolname = 'taiwa_job_writer') THEN
    GRANT SELECT ON taiwa_schema TO taiwa_job_writer;
    GRANT SELECT, INSERT, UPDATE, DELETE ON jobs, job_versions TO taiwa_job_writer;
  END IF;
END $$;
SELECT taiwa_grant_roles();
