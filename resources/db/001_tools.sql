-- Taiwa shop server, migration 1: the tool crib (docs/shop-server.md).
-- The SQLite library's versions 1-7 as one starting schema, plus what a
-- shared server needs: a row version per tool (optimistic locking), the
-- holders, and a change log (who, station, when, old and new values) that
-- a trigger fills and announces on channel taiwa_tools (LISTEN/NOTIFY).
-- Applied on connect by core/tools/pg_tool_store.cpp, inside one transaction.
CREATE TABLE tools (
  id integer PRIMARY KEY CHECK (id BETWEEN 1 AND 999),
  name text NOT NULL, type text NOT NULL, diameter double precision NOT NULL,
  corner_radius double precision NOT NULL DEFAULT 0, taper_angle double precision NOT NULL DEFAULT 0,
  point_angle double precision NOT NULL DEFAULT 118, flute_length double precision NOT NULL DEFAULT 0,
  stickout double precision NOT NULL DEFAULT 0, holder text NOT NULL DEFAULT '',
  flutes integer NOT NULL DEFAULT 2, life_minutes double precision NOT NULL DEFAULT 0,
  used_minutes double precision NOT NULL DEFAULT 0, centre_cutting boolean NOT NULL DEFAULT true,
  turning text NOT NULL DEFAULT '', holder_diameter double precision NOT NULL DEFAULT 0,
  holder_length double precision NOT NULL DEFAULT 0,
  row_version bigint NOT NULL DEFAULT 1);
CREATE TABLE cutting_data (
  tool_id integer NOT NULL REFERENCES tools(id) ON DELETE CASCADE, material text NOT NULL,
  position integer NOT NULL, surface_speed double precision NOT NULL,
  feed_per_tooth double precision NOT NULL, plunge_factor double precision NOT NULL,
  PRIMARY KEY (tool_id, material));
CREATE TABLE tool_names (
  tool_id integer NOT NULL REFERENCES tools(id) ON DELETE CASCADE, language text NOT NULL, name text NOT NULL,
  PRIMARY KEY (tool_id, language));
-- The shop's holders by name (a tool's `holder` names one; not enforced, a
-- name the crib does not list yet is still a holder).
CREATE TABLE holders (
  name text PRIMARY KEY, nose_diameter double precision NOT NULL DEFAULT 0,
  nose_length double precision NOT NULL DEFAULT 0, note text NOT NULL DEFAULT '');
CREATE TABLE tool_changes (
  id bigserial PRIMARY KEY, tool_id integer NOT NULL, operation text NOT NULL,
  who text NOT NULL DEFAULT session_user, station text NOT NULL DEFAULT current_setting('application_name'),
  at timestamptz NOT NULL DEFAULT now(), old_values jsonb, new_values jsonb);
CREATE INDEX tool_changes_by_tool ON tool_changes (tool_id, at);

-- Every update of a tool row gives it the next version, whoever writes it.
CREATE FUNCTION taiwa_tools_version() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
  NEW.row_version := OLD.row_version + 1;
  RETURN NEW;
END $$;
CREATE TRIGGER tools_version BEFORE UPDATE ON tools FOR EACH ROW EXECUTE FUNCTION taiwa_tools_version();

-- Every change of a tool row is logged and announced to the stations.
CREATE FUNCTION taiwa_tools_changed() RETURNS trigger LANGUAGE plpgsql AS $$
DECLARE
  tid integer := CASE WHEN TG_OP = 'DELETE' THEN OLD.id ELSE NEW.id END;
  ver bigint := CASE WHEN TG_OP = 'DELETE' THEN OLD.row_version ELSE NEW.row_version END;
BEGIN
  INSERT INTO tool_changes (tool_id, operation, old_values, new_values)
  VALUES (tid, TG_OP,
          CASE WHEN TG_OP = 'INSERT' THEN NULL ELSE to_jsonb(OLD) END,
          CASE WHEN TG_OP = 'DELETE' THEN NULL ELSE to_jsonb(NEW) END);
  PERFORM pg_notify('taiwa_tools', json_build_object('id', tid, 'version', ver, 'operation', TG_OP,
                    'who', session_user, 'station', current_setting('application_name'))::text);
  RETURN NULL;
END $$;
CREATE TRIGGER tools_changed AFTER INSERT OR UPDATE OR DELETE ON tools
  FOR EACH ROW EXECUTE FUNCTION taiwa_tools_changed();
