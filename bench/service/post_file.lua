-- wrk script: POST the file named by the environment variable BODY_FILE with the content type
-- CONTENT_TYPE (default text/csv) on every request. Used by bench/service/load.sh.
local f = assert(io.open(os.getenv("BODY_FILE"), "rb"))
wrk.method = "POST"
wrk.body = f:read("*a")
f:close()
wrk.headers["Content-Type"] = os.getenv("CONTENT_TYPE") or "text/csv"
